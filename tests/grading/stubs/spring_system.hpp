#pragma once
// The judge's spring_system.hpp (ex 2.1): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/problems/affine_system.hpp>
#include <kit/problems/spring.hpp>

#include "remote/fields/affine_system.hpp"
#include "remote/fields/spring.hpp"
#include "remote/judge.hpp"

namespace kit {
inline AffineSystem<2> spring_system(const Spring& spring) {
  return remote::call<AffineSystem<2>>("spring_system", spring);
}
}  // namespace kit
