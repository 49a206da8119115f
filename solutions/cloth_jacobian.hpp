#pragma once
// Ex 7.1: the stiffness block of one cloth spring (lecture, "Schéma implicite": the implicit step
// needs ∂f/∂x; ERRATA item 14). With x = x_a − x_b, l = |x|, x̂ = x/l and f_a = −K (l − L0) x̂:
//   ∂f_a/∂x_a = −K [ x̂x̂ᵀ + (1 − L0/l)(I − x̂x̂ᵀ) ]                                      [N/m]
// The first term resists a change of length; the second, a turn of the spring, and it is
// negative when the spring is compressed (l < L0). There it makes the implicit matrix
// indefinite, so the usual remedy clamps (1 − L0/l) to max(0, 1 − L0/l). The other blocks follow:
// ∂f_a/∂x_b = ∂f_b/∂x_a = −∂f_a/∂x_a and ∂f_b/∂x_b = ∂f_a/∂x_a.
#include <kit/base/not_implemented.hpp>
#include <kit/cloth/cloth_implicit_kernels.hpp>

namespace kit {

/// ∂f_a/∂x_a of a spring from a (at xa [m]) to b (at xb [m]), rest length `rest` [m], stiffness
/// K [N/m]; (1 − L0/l) clamped to ≥ 0 when `clamp`. A spring of zero length has no direction:
/// its block is zero.
inline Mat3 spring_stiffness_block(const Vec3& xa, const Vec3& xb, double rest, double stiffness,
                                   bool clamp) {
  // BEGIN SOLUTION ex 7.1: x̂ = (xa − xb)/l; P = x̂x̂ᵀ; c = 1 − L0/l (max(0, c) if clamp); −K [P + c (I − P)]
  const Vec3 d = xa - xb;
  const double length = d.norm();
  if (length == 0) return Mat3::Zero();
  const Vec3 unit = d / length;
  const Mat3 along = unit * unit.transpose();
  double turn = 1 - rest / length;
  if (clamp && turn < 0) turn = 0;
  return -stiffness * (along + turn * (Mat3::Identity() - along));
  // END SOLUTION
}

}  // namespace kit
