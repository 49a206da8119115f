#pragma once
// The random numbers of a sprite scene: the kit's one source (base/random.hpp). SpriteRandom is
// its name before the library took its layers, kept one release for exercise copies that use it.
#include <kit/base/random.hpp>

namespace kit {

using SpriteRandom = Random;

}  // namespace kit
