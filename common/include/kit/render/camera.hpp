#pragma once
// The one camera of the kit's pictures (sprites, cloth, rigid bodies): where it looks from
// (Camera, as scene files give it) and the pinhole projection it makes onto an image of a given
// size (Pinhole). World y is up; image row 0 is the top, so world up is towards smaller rows.
#include <optional>

#include <kit/base/vec3.hpp>

namespace kit {

/// Where a camera stands and looks.
struct Camera {
  Vec3 position{0, 2, 10};  ///< [m]
  Vec3 target{0, 2, 0};     ///< [m]
  double fov_deg = 45;      ///< vertical field of view [deg], in (0, 180)
};

/// Where a point lands: continuous pixel coordinates (pixel (i, j) covers [i, i+1) × [j, j+1),
/// so the image centre is (width/2, height/2)) and its depth along the view axis [m].
struct Projected {
  double px = 0, py = 0;
  double depth = 0;
};

class Pinhole {
 public:
  /// Points nearer than this along the view axis are not drawn [m]: a sprite there would cover
  /// the whole image, and at depth ≤ 0 the projection flips.
  static constexpr double near_depth = 0.05;

  /// Throws kit::UsageError when position and target coincide or fov_deg is outside (0, 180),
  /// std::invalid_argument when the image has fewer than 1 × 1 pixels.
  Pinhole(const Camera& camera, int width, int height);

  /// Perspective projection: with the camera frame (right r, up u, forward f) and d = p − eye,
  /// depth = d·f, px = W/2 + F·(d·r)/depth, py = H/2 − F·(d·u)/depth. Nullopt when
  /// depth < near_depth (behind the camera or too close).
  std::optional<Projected> project(double x, double y, double z) const;

  /// The inverse of project: the point at `depth` [m] along the view axis that lands on (px, py)
  /// is eye() + depth·ray(px, py); the ray's component along the view axis is 1. For ray casting
  /// (the cloth renderer's spheres and ground).
  Vec3 ray(double px, double py) const;
  Vec3 eye() const { return eye_; }
  Vec3 forward() const { return forward_; }

  /// Pixels that one metre spans, facing the camera at `depth` [px/m]: F/depth.
  double pixels_per_metre(double depth) const { return focal_px_ / depth; }
  /// Focal length in pixels: F = (H/2)/tan(fov/2), fov vertical.
  double focal_px() const { return focal_px_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  Vec3 eye_, right_, up_, forward_;  // all set by the constructor
  double focal_px_ = 0;
  int width_ = 0, height_ = 0;
};

}  // namespace kit
