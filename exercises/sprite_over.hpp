#pragma once
// Ex 5.3: one sprite composited "over" the image (Porter & Duff 1984). The sprite is straight
// (non-premultiplied) colour c with opacity α at each of its pixels; the image is opaque, so
//   dst ← α·c + (1 − α)·dst   for each of r, g, b.
// A sprite near the border of the frame hangs over it: only its pixels inside the image count.
#include <kit/base/not_implemented.hpp>
#include <kit/render/image.hpp>
#include <kit/sprites/sprite_tile.hpp>

namespace kit {

/// Composites every pixel of `tile` whose image position (tile.x0 + column, tile.y0 + row) lies
/// inside `image` onto that image pixel; pixels outside the image are ignored, and an α of 0
/// leaves its image pixel exactly as it was.
inline void composite_over(Image& image, const SpriteTile& tile) {
  // TODO(ex 5.3): for each tile pixel inside the image, dst = alpha·c + (1 − alpha)·dst per channel
  throw kit::NotImplemented("ex 5.3", "sprite_over.hpp");
}

}  // namespace kit
