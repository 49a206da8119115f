#pragma once
// The judge's fem_strain.hpp (ex 9.1): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/fem/fem_element.hpp>

#include "remote/fields/fem_element.hpp"
#include "remote/judge.hpp"

namespace kit {
inline Matrix32 deformation_gradient(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                     const Matrix2& rest_inverse) {
  return remote::call<Matrix32>("deformation_gradient", x0, x1, x2, rest_inverse);
}
inline Matrix2 green_strain(const Matrix32& F) { return remote::call<Matrix2>("green_strain", F); }
}  // namespace kit
