#pragma once
// The pictures a sprite carries (chapter 5): four small procedural textures built in, or a PNG.
// A built-in texture is white with its shape in the alpha; the particle's colour tints it when drawn.
#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace kit {

/// Straight (non-premultiplied) linear RGBA, 4 floats per texel in [0, 1], row 0 at the top.
struct Texture {
  int width = 0, height = 0;
  std::vector<float> rgba;

  const float* texel(int x, int y) const {
    return rgba.data() +
           4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
  }
};

/// The names builtin_texture knows, in the order the error messages list them.
inline constexpr std::array<std::string_view, 4> builtin_texture_names{"soft", "spark", "flake", "smoke"};

/// A 64 × 64 procedural texture: "soft" (a disc with a Gaussian falloff), "spark" (a bright core
/// with a four-pointed star), "flake" (a six-armed snowflake), "smoke" (a noisy puff, the same
/// noise every run). Each is transparent at its border, so the sprite's square never shows.
/// Throws kit::UsageError naming `name` and listing the built-in names when it is none of them.
Texture builtin_texture(std::string_view name);

/// A built-in texture by name, or else a PNG file at that path (8-bit values / 255, read as
/// linear). Throws kit::UsageError naming it, with the built-in names, when it is neither.
Texture texture_for(const std::string& name_or_png_path);

/// The texture averaged 2 × 2 repeatedly down to 1 × 1: level 0 is `texture` itself, each next
/// level half the size (rounded up). Colours are averaged weighted by alpha (premultiplied), so
/// a transparent texel's colour does not bleed in. A sprite a few pixels wide samples the level
/// whose texels are about one pixel, so it shows its average, not a point of its centre.
std::vector<Texture> mip_levels(const Texture& texture);

/// Bilinear interpolation of the four texels around (u, v), with u across and v down in [0, 1]
/// over the whole texture; texel centres sit at ((i + ½)/width, (j + ½)/height); outside the
/// centres the edge texels extend (clamp to edge). Writes r, g, b, a to `out`.
inline void sample_bilinear(const Texture& t, float u, float v, float* out) {
  const float x = std::clamp(u * static_cast<float>(t.width) - 0.5f, 0.0f, static_cast<float>(t.width - 1));
  const float y = std::clamp(v * static_cast<float>(t.height) - 0.5f, 0.0f, static_cast<float>(t.height - 1));
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const int x1 = std::min(x0 + 1, t.width - 1), y1 = std::min(y0 + 1, t.height - 1);
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  const float* a = t.texel(x0, y0);
  const float* b = t.texel(x1, y0);
  const float* c = t.texel(x0, y1);
  const float* d = t.texel(x1, y1);
  for (int k = 0; k < 4; ++k) {
    const float top = a[k] + fx * (b[k] - a[k]);
    const float bottom = c[k] + fx * (d[k] - c[k]);
    out[k] = top + fy * (bottom - top);
  }
}

}  // namespace kit
