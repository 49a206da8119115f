#pragma once
// The judge's rigid_quaternion_step.hpp (ex 8.2): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/rigid/rigid_body.hpp>

#include "remote/judge.hpp"

namespace kit {
inline Quat quaternion_step(const Quat& q, const Vec3& omega, double h) {
  return remote::call<Quat>("quaternion_step", q, omega, h);
}
}  // namespace kit
