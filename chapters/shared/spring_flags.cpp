#include "spring_flags.hpp"

namespace kit {

void add_spring_flags(ChapterApp& app, Spring& spring, Vec2& u0, double max_stiffness) {
  app.add_real("--mass", spring.mass, "mass m [kg]", between(1e-6, 1e6));
  app.add_real("--stiffness", spring.stiffness, "stiffness K [N/m]", between(1e-6, max_stiffness));
  app.add_real("--damping", spring.damping, "viscous damping μ [N·s/m]", between(0.0, 1e12));
  app.add_real("--rest-length", spring.rest_length, "rest length L0 [m]", between(-1e6, 1e6));
  app.add_real("--x0", u0[0], "initial position x(0) [m]", between(-1e6, 1e6));
  app.add_real("--v0", u0[1], "initial velocity v(0) [m/s]", between(-1e6, 1e6));
}

void require_motion(const Spring& spring, const Vec2& u0) {
  if (u0 == Vec2(spring.rest_length, 0.0))
    throw UsageError("--x0 equals --rest-length and --v0 is 0: the spring starts at rest and never moves");
}

}  // namespace kit
