#pragma once
// The judge's cloth_spring_force.hpp (ex 6.1): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/cloth/cloth.hpp>

#include "remote/fields/cloth.hpp"
#include "remote/judge.hpp"

namespace kit {
inline Vec3 spring_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double rest,
                         const SpringFamily& family) {
  return remote::call<Vec3>("spring_force", xa, xb, va, vb, rest, family);
}
}  // namespace kit
