#pragma once
// The lecture's auxiliary quantities: ω(t) = I(t)⁻¹ L(t) with I(t) = R I_body Rᵀ, hence
//   ω = R I_body⁻¹ Rᵀ L,
// three matrix-vector products and no inverse at run time (I_body⁻¹ is computed once per shape).
// Rᵀ is R's inverse only while R is a rotation: with an R that has drifted (explicit Euler on R)
// this is what the lecture's formula reads, and part of why that integrator goes wrong.
#include <kit/base/not_implemented.hpp>
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// ω [rad/s, world] of a body at orientation R with body-frame inverse inertia I_body⁻¹
/// [1/(kg·m²)] and angular momentum L [kg·m²/s, world].
inline Vec3 angular_velocity(const Mat3& R, const Mat3& inverse_inertia_body, const Vec3& L) {
  // TODO(ex 8.3): L to the body frame (Rᵀ), through I_body⁻¹, back to the world (R)
  throw kit::NotImplemented("ex 8.3", "rigid_angular_velocity.hpp");
}

}  // namespace kit
