#pragma once
// The orientation as a unit quaternion q (Shoemake 1985): with ω [rad/s] in the world frame,
//   q' = ½ (0, ω) ⊗ q,
// four numbers instead of nine and one constraint, |q| = 1, instead of six. One explicit Euler
// step of it, then q / |q|: the step leaves the unit sphere by O(h²) and the division brings it
// back, so q stays a rotation whatever h (its error in the motion is still first order).
#include <kit/base/not_implemented.hpp>
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// One explicit Euler step of q' = ½ (0, ω) ⊗ q over h [s], then renormalised to |q| = 1.
inline Quat quaternion_step(const Quat& q, const Vec3& omega, double h) {
  // BEGIN SOLUTION ex 8.2: q + h/2 · (0, ω) ⊗ q (Eigen's * is the Hamilton product), then normalise
  const Quat rate = Quat(0, omega.x(), omega.y(), omega.z()) * q;
  return Quat(q.coeffs() + 0.5 * h * rate.coeffs()).normalized();
  // END SOLUTION
}

}  // namespace kit
