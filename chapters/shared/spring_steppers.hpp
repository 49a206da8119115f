#pragma once
// One step of each scheme on the spring, behind one signature, for the chapters that compare
// them. Not an exercise: it only wires the schemes of ex 2.1–3.2 to the spring.
#include <functional>
#include <stdexcept>
#include <vector>

#include <kit/app/report.hpp>
#include <kit/ode/scheme.hpp>
#include <kit/problems/spring.hpp>

#include "explicit_euler.hpp"
#include "implicit_euler_spring.hpp"
#include "midpoint.hpp"
#include "rk4.hpp"
#include "spring_system.hpp"
#include "symplectic_euler.hpp"

namespace kit {

/// u_k → u_{k+1} for `scheme` on `spring` with step dt [s]. The spring is autonomous, so t is
/// passed as 0.
inline std::function<Vec2(const Vec2&)> spring_stepper(Scheme scheme, const Spring& spring, double dt) {
  switch (scheme) {  // A and b (ex 2.1) only for the schemes that use them
    case Scheme::explicit_euler:
      return [euler = ExplicitEulerAffine<2>(spring_system(spring), dt)](const Vec2& u) {
        return euler.step(u);
      };
    case Scheme::implicit_euler:
      return [spring, dt](const Vec2& u) { return implicit_euler_spring_step(spring, u, dt); };
    case Scheme::symplectic_euler:
      return [spring, dt](const Vec2& u) {
        const auto accel = [&](double, const Vec<1>& x, const Vec<1>& v) {
          const double force = spring.stiffness * (spring.rest_length - x[0]) - spring.damping * v[0];  // [N]
          return Vec<1>(force / spring.mass);
        };
        return symplectic_euler_step(accel, 0.0, u, dt);
      };
    case Scheme::midpoint:
      return
          [system = spring_system(spring), dt](const Vec2& u) { return midpoint_step(system, 0.0, u, dt); };
    case Scheme::rk4:
      return [system = spring_system(spring), dt](const Vec2& u) { return rk4_step(system, 0.0, u, dt); };
  }
  throw std::invalid_argument("unknown scheme");
}

/// The schemes whose exercises are written, each probed with one step of dt [s] from u0; the
/// report names every other one and the exercise it waits for.
inline std::vector<Scheme> written_schemes(Report& report, const Spring& spring, const Vec2& u0, double dt) {
  std::vector<Scheme> schemes;
  for (Scheme s : all_schemes)
    if (report.attempt(name(s), [&] { spring_stepper(s, spring, dt)(u0); })) schemes.push_back(s);
  return schemes;
}

}  // namespace kit
