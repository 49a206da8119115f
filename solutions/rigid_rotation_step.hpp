#pragma once
// The lecture's rotation ODE as written ("Mécanique du solide"): R' = ω* R, where ω* is the
// cross-product matrix of the angular velocity ω [rad/s] in the world frame (ERRATA 15: the
// lecture's "*" means ω* a = ω × a for every vector a). One explicit Euler step of it,
//   R_{k+1} = R_k + h ω* R_k,
// leaves the rotations: RᵀR becomes RᵀR + h² Rᵀ(ω*)ᵀω* R (ω* is antisymmetric, so the first-order
// terms cancel), so R stretches and shears a little more every step (chapter 8).
#include <kit/base/not_implemented.hpp>
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// The cross-product matrix ω*: skew(w) * a == w.cross(a) for every a.
inline Mat3 skew(const Vec3& w) {
  // BEGIN SOLUTION ex 8.1: the antisymmetric matrix whose product with a is w × a
  Mat3 S;
  S << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return S;
  // END SOLUTION
}

/// One explicit Euler step of R' = ω* R over h [s], ω [rad/s] in the world frame: R + h ω* R.
inline Mat3 explicit_rotation_step(const Mat3& R, const Vec3& omega, double h) {
  // BEGIN SOLUTION ex 8.1: the lecture's step, with R's rate ω* R held for the whole step
  return R + h * skew(omega) * R;
  // END SOLUTION
}

}  // namespace kit
