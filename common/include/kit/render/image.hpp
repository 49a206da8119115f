#pragma once
// The picture a sprite renderer draws into (chapter 5): linear float RGB, so that blending adds
// and averages light, not encoded 8-bit values; quantised only when written to a PNG.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace kit {

/// A colour: linear RGB, each in [0, 1] (more, before a picture is clamped). Not a Vec3: colours
/// are mixed and scaled, never rotated or projected.
using Colour = std::array<double, 3>;

/// A linear RGB image, 3 floats per pixel, rows stored top to bottom (row 0 is the top).
/// Values may exceed 1 (additive glows); write_png clamps them only at output.
struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  ///< width·height·3 values, row-major

  Image() = default;
  /// A width × height image filled with `fill`. Throws std::invalid_argument unless both are ≥ 1.
  Image(int width, int height, Colour fill);

  /// Sets every pixel to `colour`.
  void fill(Colour colour);
  float* pixel(int x, int y) { return rgb.data() + offset(x, y); }
  const float* pixel(int x, int y) const { return rgb.data() + offset(x, y); }

 private:
  std::size_t offset(int x, int y) const {
    return 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
  }
};

/// The 8-bit value write_png stores for a linear channel value v: round(255·clamp(v, 0, 1)),
/// halves rounded away from zero; NaN is stored as 0. No gamma curve is applied: the linear
/// value is written as it is (a PNG viewer will show it darker than an sRGB-encoded one).
std::uint8_t to_byte(float v);

/// Writes `image` as an 8-bit RGB PNG (each channel through to_byte), atomically: through a
/// temporary sibling renamed into place. Throws std::runtime_error naming `path` when it cannot
/// be written; no file (final or temporary) is left behind then.
void write_png(const Image& image, const std::filesystem::path& path);

/// An 8-bit RGBA picture as a PNG file holds it: 4 bytes per pixel, row 0 at the top.
struct Rgba8 {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

/// Reads any PNG (grey, grey+alpha, RGB, RGBA, palette) as RGBA; a missing alpha reads as 255.
/// Throws std::runtime_error naming `path` and the decoder's reason when it cannot be read.
Rgba8 read_png(const std::filesystem::path& path);

}  // namespace kit
