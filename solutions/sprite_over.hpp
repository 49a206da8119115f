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
  // BEGIN SOLUTION ex 5.3: for each tile pixel inside the image, dst = alpha·c + (1 − alpha)·dst per channel
  for (int row = 0; row < tile.height; ++row) {
    const int y = tile.y0 + row;
    if (y < 0 || y >= image.height) continue;
    for (int column = 0; column < tile.width; ++column) {
      const int x = tile.x0 + column;
      if (x < 0 || x >= image.width) continue;
      const float* source = tile.at(column, row);
      const float alpha = source[3], keep = 1.0f - alpha;
      float* target = image.pixel(x, y);
      for (int channel = 0; channel < 3; ++channel)
        target[channel] = alpha * source[channel] + keep * target[channel];
    }
  }
  // END SOLUTION
}

}  // namespace kit
