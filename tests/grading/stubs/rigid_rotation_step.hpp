#pragma once
// The judge's rigid_rotation_step.hpp (ex 8.1): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/rigid/rigid_body.hpp>

#include "remote/judge.hpp"

namespace kit {
inline Mat3 skew(const Vec3& w) { return remote::call<Mat3>("skew", w); }
inline Mat3 explicit_rotation_step(const Mat3& R, const Vec3& omega, double h) {
  return remote::call<Mat3>("explicit_rotation_step", R, omega, h);
}
}  // namespace kit
