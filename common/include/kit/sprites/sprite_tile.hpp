#pragma once
// One sprite as the renderer has rasterized it (chapter 5): a rectangle of pixels of the image,
// each with the straight (non-premultiplied) linear colour the sprite shows there and the opacity
// it has there (texel alpha × particle alpha × covered fraction). Compositing it onto the image
// "over" is ex 5.3 (solutions/sprite_over.hpp).
#include <vector>

namespace kit {

struct SpriteTile {
  int x0 = 0, y0 = 0;         ///< image column and row of the tile's top-left pixel (may be < 0)
  int width = 0, height = 0;  ///< [px]
  std::vector<float> rgba;    ///< width·height pixels, row by row: r, g, b, alpha, each in [0, 1]

  /// Pixel (column, row) of the tile, 0 ≤ column < width, 0 ≤ row < height.
  const float* at(int column, int row) const { return rgba.data() + 4 * (row * width + column); }
  float* at(int column, int row) { return rgba.data() + 4 * (row * width + column); }
  /// Resizes to width × height at (x0, y0), every pixel transparent black.
  void reset(int left, int top, int w, int h) {
    x0 = left, y0 = top, width = w, height = h;
    rgba.assign(std::size_t(4 * w * h), 0.0f);
  }
};

}  // namespace kit
