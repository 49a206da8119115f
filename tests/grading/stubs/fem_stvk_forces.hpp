#pragma once
// The judge's fem_stvk_forces.hpp (ex 9.2): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/fem/fem_element.hpp>

#include "remote/fields/fem_element.hpp"
#include "remote/judge.hpp"

namespace kit {
inline Matrix2 stvk_stress(const Matrix2& E, const Lame& lame) {
  return remote::call<Matrix2>("stvk_stress", E, lame);
}
inline ElementForces stvk_forces(const Matrix32& F, const Matrix2& rest_inverse, double rest_volume,
                                 const Lame& lame) {
  return remote::call<ElementForces>("stvk_forces", F, rest_inverse, rest_volume, lame);
}
}  // namespace kit
