#pragma once
// The judge's fem_stvk_stiffness.hpp (ex 9.3): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/fem/fem_element.hpp>

#include "remote/fields/fem_element.hpp"
#include "remote/judge.hpp"

namespace kit {
inline Matrix9 stvk_stiffness(const Matrix32& F, const Matrix2& rest_inverse, double rest_volume,
                              const Lame& lame) {
  return remote::call<Matrix9>("stvk_stiffness", F, rest_inverse, rest_volume, lame);
}
}  // namespace kit
