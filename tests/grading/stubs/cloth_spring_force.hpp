#pragma once
// The judge's cloth_spring_force.hpp (ex 6.1): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/cloth/cloth.hpp>

#include "remote/fields/cloth.hpp"
#include "remote/judge.hpp"

namespace kit {
inline Vector3 spring_force(const Vector3& xa, const Vector3& xb, const Vector3& va, const Vector3& vb,
                            double rest, const SpringFamily& family) {
  return remote::call<Vector3>("spring_force", xa, xb, va, vb, rest, family);
}
}  // namespace kit
