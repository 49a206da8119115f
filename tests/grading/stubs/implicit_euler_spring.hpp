#pragma once
// The judge's implicit_euler_spring.hpp (ex 2.2): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/problems/spring.hpp>

#include "remote/fields/spring.hpp"
#include "remote/judge.hpp"

namespace kit {
inline Vec2 implicit_euler_spring_step(const Spring& spring, const Vec2& u, double dt) {
  return remote::call<Vec2>("implicit_euler_spring_step", spring, u, dt);
}
}  // namespace kit
