#pragma once
// The two ways a sprite's pixel meets the image (chapter 5; Porter & Duff 1984, Reeves 1983), on
// one linear RGB pixel. The source is straight (non-premultiplied) colour c with opacity α; the
// destination is the image, always opaque.
#include <kit/sprites/sprite_scene.hpp>

namespace kit {

/// A straight (non-premultiplied) linear colour.
struct Rgb {
  float r = 0, g = 0, b = 0;
};

/// Porter–Duff "over" onto an opaque destination: dst ← α·c + (1 − α)·dst. The result depends
/// on the order sprites are drawn in, hence the back-to-front sort.
inline void blend_over(float* dst, Rgb c, float alpha) {
  const float keep = 1.0f - alpha;
  dst[0] = alpha * c.r + keep * dst[0];
  dst[1] = alpha * c.g + keep * dst[1];
  dst[2] = alpha * c.b + keep * dst[2];
}

/// Additive: dst ← dst + α·c. Light adds, so the order does not matter (up to float rounding);
/// nothing is clamped here, values above 1 are clamped only when the image is written.
inline void blend_additive(float* dst, Rgb c, float alpha) {
  dst[0] += alpha * c.r;
  dst[1] += alpha * c.g;
  dst[2] += alpha * c.b;
}

/// The rule as a compile-time choice, so a drawing loop carries no branch per pixel.
template <Blend mode>
inline void blend(float* dst, Rgb c, float alpha) {
  if constexpr (mode == Blend::over)
    blend_over(dst, c, alpha);
  else
    blend_additive(dst, c, alpha);
}

}  // namespace kit
