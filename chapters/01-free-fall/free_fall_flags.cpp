#include "free_fall_flags.hpp"

#include <cmath>

#include <fmt/format.h>

namespace kit {

void add_free_fall_flags(ChapterApp& app, FreeFall& fall, double& dt, double& t_end, double& dt_min) {
  app.add_real("--x0", fall.x0, "initial height x(0) [m], y axis up", between(-1e6, 1e6));
  app.add_real("--v0", fall.v0, "initial velocity v(0) [m/s], positive upward", between(-1e4, 1e4));
  auto gravity = between(-1e3, 1e3);
  gravity.nonzero = true;
  app.add_real("--g", fall.g, "gravitational acceleration g [m/s^2], negative = downward", gravity);
  app.add_real("--dt", dt, "time step [s]", positive(10.0));
  app.add_real("--t-end", t_end, "final time T [s], a whole number of steps", positive(1e4));
  app.add_real("--dt-min", dt_min,
               "smallest time step asked of the round-off sweep [s]; raised when "
               "T/dt-min exceeds its budget of steps",
               between(1e-12, 1e-3));
}

void require_measurable(const FreeFall& fall, double t_end, double dt_min) {
  if (std::abs(fall.g) < 1e-3)
    throw UsageError(fmt::format("--g {}: expected |g| >= 1e-3 m/s^2, or the errors this chapter measures "
                                 "vanish in round-off",
                                 fall.g));
  if (!(dt_min * 10 <= t_end))
    throw UsageError(fmt::format("--dt-min {} s: expected at most --t-end/10 = {:.3g} s, so that the "
                                 "round-off sweep spans a decade of dt",
                                 dt_min, t_end / 10));
}

}  // namespace kit
