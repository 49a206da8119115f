#pragma once
// The judge's sprite_over.hpp (ex 5.3): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/render/image.hpp>
#include <kit/sprites/sprite_tile.hpp>

#include "remote/fields/image.hpp"
#include "remote/judge.hpp"

namespace kit {
inline void composite_over(Image& image, const SpriteTile& tile) {
  remote::call<void>("composite_over", remote::inout(image), tile);
}
}  // namespace kit
