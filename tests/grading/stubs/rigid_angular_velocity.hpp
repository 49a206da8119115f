#pragma once
// The judge's rigid_angular_velocity.hpp (ex 8.3): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/rigid/rigid_body.hpp>

#include "remote/judge.hpp"

namespace kit {
inline Vec3 angular_velocity(const Mat3& R, const Mat3& inverse_inertia_body, const Vec3& L) {
  return remote::call<Vec3>("angular_velocity", R, inverse_inertia_body, L);
}
}  // namespace kit
