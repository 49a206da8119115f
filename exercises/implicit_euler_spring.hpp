#pragma once
// Implicit Euler on the damped spring, solved by hand (lecture, "Euler implicite"):
//   x_{k+1} = x_k + Δt v_{k+1},   v_{k+1} = v_k + Δt (K (L0 − x_{k+1}) − μ v_{k+1}) / m.
// No matrix is formed: eliminating x_{k+1} leaves one division.
#include <kit/base/not_implemented.hpp>
#include <kit/problems/spring.hpp>

namespace kit {

/// One implicit Euler step of the spring. Unconditionally stable: every mode's amplitude is
/// multiplied by |1/(1 − λΔt)| < 1 (ERRATA item 5), and the motion settles at L0.
inline Vec2 implicit_euler_spring_step(const Spring& spring, const Vec2& u, double dt) {
  // TODO(ex 2.2): substitute x_{k+1} into the v equation, solve for v_{k+1}, then x_{k+1}
  throw kit::NotImplemented("ex 2.2", "implicit_euler_spring.hpp");
}

}  // namespace kit
