#pragma once
// The judge's cloth_jacobian.hpp (ex 7.1): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/cloth/cloth_implicit_kernels.hpp>

#include "remote/fields/cloth_implicit_kernels.hpp"
#include "remote/judge.hpp"

namespace kit {
inline Mat3 spring_stiffness_block(const Vec3& xa, const Vec3& xb, double rest, double stiffness,
                                   bool clamp) {
  return remote::call<Mat3>("spring_stiffness_block", xa, xb, rest, stiffness, clamp);
}
}  // namespace kit
