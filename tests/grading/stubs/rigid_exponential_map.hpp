#pragma once
// The judge's rigid_exponential_map.hpp (ex 8.4): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/rigid/rigid_body.hpp>

#include "remote/judge.hpp"

namespace kit {
inline Mat3 exponential_map_step(const Mat3& R, const Vec3& omega, double h) {
  return remote::call<Mat3>("exponential_map_step", R, omega, h);
}
}  // namespace kit
