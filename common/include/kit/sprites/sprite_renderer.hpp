#pragma once
// Draws particles as textured, camera-facing squares (chapter 5; Reeves 1983, Porter & Duff
// 1984): "over" sprites sorted back to front first, then additive glows, into a linear image.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <kit/render/camera.hpp>
#include <kit/render/image.hpp>
#include <kit/sprites/particles.hpp>
#include <kit/sprites/sprite_scene.hpp>
#include <kit/sprites/sprite_texture.hpp>
#include <kit/sprites/sprite_tile.hpp>

namespace kit {

/// What one frame cost. Every alive particle is either drawn or culled.
struct RenderStats {
  long sprites_drawn = 0;
  long sprites_culled = 0;  ///< behind the near plane, wholly off the image, size or alpha ≤ 0
  long pixels_blended = 0;  ///< pixel writes, summed over sprites
};

/// Composites one rasterized sprite onto the image, "over" (ex 5.3, plugged in by the chapter).
using CompositeOver = void (*)(Image& image, const SpriteTile& tile);

class SpriteRenderer {
 public:
  /// Loads each emitter's texture (kit::UsageError for an unknown name or unreadable PNG) and
  /// sets up the camera for a width × height image.
  SpriteRenderer(const SpriteScene& scene, int width, int height);

  /// Clears `out` to the scene's background (resizing it once if its size differs), then draws
  /// particles [0, size()): each a square of edge size_m [m] facing the camera, so
  /// size_m·pixels_per_metre(depth) pixels wide, textured with its emitter's texture, tinted by
  /// its colour, opacity = texel alpha × particle alpha × the pixel's covered fraction. Edges are
  /// box-filtered (a pixel half covered gets half the alpha), so a sprite smaller than a pixel
  /// still adds its area's worth and does not flicker as it moves. Nothing is allocated once
  /// the buffers have grown to the largest frame. Throws std::out_of_range for a particle whose
  /// emitter index the scene does not have.
  RenderStats render(const Particles& particles, Image& out);

  const Pinhole& camera() const { return camera_; }
  /// From now on, "over" sprites are rasterized into a SpriteTile and composited by `composite`
  /// (the student's ex 5.3); nullptr: the renderer blends them itself, pixel by pixel, as it
  /// always does additive ones. Both give the same image for a correct `composite`.
  void composite_over_with(CompositeOver composite) { composite_over_ = composite; }

 private:
  // One visible particle, placed on the image.
  struct Sprite {
    double px, py;        // centre [px]
    double edge;          // [px]
    double depth;         // [m]
    std::uint32_t index;  // into the particles
  };
  // Rasterizes `sprite` into `target`: ImageTarget<mode> blends into the image, TileTarget
  // writes the tile the student's compositing reads.
  template <class Target>
  long draw(const Sprite& sprite, const Particles& particles, Image& out, Target target);

  Pinhole camera_;
  Colour background_;
  std::vector<Blend> blend_of_emitter_;
  std::vector<std::vector<Texture>> textures_;        // mip_levels of each distinct texture
  std::map<std::string, std::size_t> texture_index_;  // texture name or path -> textures_
  std::vector<std::size_t> texture_of_emitter_;       // emitter -> textures_
  std::vector<Sprite> over_, additive_;               // this frame's sprites, kept for their capacity
  // Per image column of the sprite being drawn: the two texel columns either side of the pixel
  // centre, the weight of the right one, and the fraction of the pixel the square covers.
  struct ColumnSample {
    int left, right;
    float toward_right;
    float coverage;
  };
  std::vector<ColumnSample> columns_;
  CompositeOver composite_over_ = nullptr;
  SpriteTile tile_;  // reused by every "over" sprite when composite_over_ is set
};

}  // namespace kit
