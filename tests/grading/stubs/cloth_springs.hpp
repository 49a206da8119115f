#pragma once
// The judge's cloth_springs.hpp (ex 6.2): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/cloth/cloth.hpp>

#include "remote/fields/cloth.hpp"
#include "remote/judge.hpp"

namespace kit {
inline Springs build_springs(const ClothGrid& grid, const SpringLayout& layout) {
  return remote::call<Springs>("build_springs", grid, layout);
}
}  // namespace kit
