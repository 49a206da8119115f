#pragma once
// The software rasteriser the 3D renderers share (the cloth of chapters 6 and 7, the rigid bodies of
// chapter 8): a picture with its depth buffer, the backdrop every pixel's ray sees first (the sky and
// a checkerboard ground, lit and shadowed), the lighting, and depth-tested triangles. All seen
// through the kit's pinhole camera (camera.hpp, y up); colours are linear RGB.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include <kit/base/vec3.hpp>
#include <kit/render/camera.hpp>
#include <kit/render/image.hpp>

namespace kit {

// The scene palette of the cloth and rigid-body pictures.
/// The background sky: cloth_sky_bottom at the horizon (and below it), blending to cloth_sky_top
/// looking 30° or more upwards, so the ground's haze meets the sky without a seam.
inline constexpr Colour cloth_sky_top{0.36, 0.45, 0.60};
inline constexpr Colour cloth_sky_bottom{0.80, 0.82, 0.85};
/// The sky's colour seen along a direction whose unit vector has this y component.
Colour cloth_sky(double elevation);
/// The key light: the unit direction towards it (world, y up), from above, in front and left.
inline const Vec3 cloth_key_light{-0.4364357804719848, 0.8728715609439696, 0.2182178902359924};
/// Light every surface gets whatever its orientation, as a fraction of full light (a surface
/// facing the key light gets 1; a dim fill light from the other side adds a little, capped at 1).
inline constexpr double cloth_ambient = 0.30;

/// The colour a + (b − a) t: t = 0 gives a, t = 1 gives b.
inline Colour mix_colours(const Colour& a, const Colour& b, double t) {
  return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
}
/// The colour c dimmed (or brightened) by the factor s.
inline Colour scale_colour(const Colour& c, double s) { return {c[0] * s, c[1] * s, c[2] * s}; }

/// A picture being drawn and its depth buffer: per pixel the depth [m, along the view axis] of
/// what it shows, +infinity where that is the sky.
struct DepthCanvas {
  Image image;
  std::vector<float> depth;

  /// A width × height canvas of `fill`, infinitely deep. Throws as Image for a bad size.
  DepthCanvas(int width, int height, const Colour& fill);
  float& depth_at(int px, int py) {
    return depth[std::size_t(py) * std::size_t(image.width) + std::size_t(px)];
  }
  void put(int px, int py, const Colour& colour) {
    float* p = image.pixel(px, py);
    p[0] = float(colour[0]), p[1] = float(colour[1]), p[2] = float(colour[2]);
  }
};

/// The unit direction towards the key light (cloth_key_light, cloth_renderer.hpp).
Vec3 key_light_direction();
/// How lit a surface of unit normal n is, as a fraction of full light in [cloth_ambient, 1]: the
/// ambient, plus Lambert (n·l clamped at 0) from the key light scaled by 1 − ambient, plus a dim
/// fill light from the opposite side so that what the key light misses keeps its shape.
double light_intensity(const Vec3& unit_normal);

/// What a ray meets: the colour it brings back and the depth there [m along the view axis;
/// +infinity for the sky].
struct RayHit {
  Colour colour{};
  double depth = std::numeric_limits<double>::infinity();
};

/// The ground's squares [m]: the checkerboard alternates every 0.25 m in x and z.
inline constexpr double ground_checker_square = 0.25;
/// Whether the key light is blocked on its way to a ground point [m] (a shadow there); an empty
/// test casts no shadow.
using ShadowTest = std::function<bool(const Vec3& ground_point)>;

/// What may stand in front of the backdrop along a ray (from the camera's eye, view-axis
/// component 1, as Pinhole::ray): given the ray and what the backdrop shows along it, it
/// replaces that with anything nearer (the cloth's spheres). Empty: nothing.
using RayForeground = std::function<void(const Vec3& ray, RayHit& hit)>;

/// Fills every pixel of `canvas` and its depth with what the ray through the pixel's centre sees:
/// the sky (cloth_sky), or, when `ground_height` [m] is given, the plane y = height as a
/// checkerboard of ground_checker_square, lit from above by the key light unless `in_shadow`
/// says it is blocked (then by the ambient alone), fading to its mean colour and then into the
/// horizon's haze once a square spans only a few pixels (it would alias); then `in_front`.
void draw_backdrop(const Pinhole& camera, const std::optional<double>& ground_height,
                   const ShadowTest& in_shadow, const RayForeground& in_front, DepthCanvas& canvas);

/// A vertex projected on the image: pixel coordinates (as Projected) and depth [m].
struct ScreenVertex {
  double px = 0, py = 0, depth = 0;
};

/// Projected coordinates beyond this many pixels mark a diverged body: edge functions of such
/// triangles would lose pixel precision, and nothing sensible is drawn from them [px].
inline constexpr double max_pixel_coordinate = 1e6;

/// Where `point` [m] lands on the image, or nullopt when it cannot be drawn: not finite, nearer
/// than Pinhole::near_depth (or behind the eye), or beyond max_pixel_coordinate.
std::optional<ScreenVertex> screen_vertex(const Pinhole& camera, const Vec3& point);

/// Fills the triangle (a, b, c), either winding, clipped to the canvas: each pixel whose centre
/// lies inside and whose depth (1/depth interpolated linearly on screen, as perspective makes it)
/// is nearer than the stored one gets the colour `shade(wa, wb, wc)` returns (a Colour), given the
/// perspective-correct barycentric weights of a, b, c (≥ 0, summing to 1) to interpolate with.
/// A tie goes to the triangle: a depth bias of 1e-4 of the depth (0.3 mm at 3 m) lets a surface
/// lying on the ground win instead of flickering against it. Returns false, drawing nothing, for
/// a triangle of no area or wholly off the canvas.
template <class Shade>
bool fill_triangle(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c, DepthCanvas& canvas,
                   Shade&& shade) {
  const double area = (b.px - a.px) * (c.py - a.py) - (b.py - a.py) * (c.px - a.px);
  const int x0 = std::max(0, int(std::floor(std::min({a.px, b.px, c.px}))));
  const int x1 = std::min(canvas.image.width - 1, int(std::ceil(std::max({a.px, b.px, c.px}))));
  const int y0 = std::max(0, int(std::floor(std::min({a.py, b.py, c.py}))));
  const int y1 = std::min(canvas.image.height - 1, int(std::ceil(std::max({a.py, b.py, c.py}))));
  if (!(std::abs(area) > 1e-12) || x0 > x1 || y0 > y1) return false;
  const double inv_area = 1 / area;
  for (int py = y0; py <= y1; ++py)
    for (int px = x0; px <= x1; ++px) {
      const double cx = px + 0.5, cy = py + 0.5;
      // Barycentric weights from edge functions; all ≥ 0 inside whatever the winding.
      const double wa = ((b.px - cx) * (c.py - cy) - (b.py - cy) * (c.px - cx)) * inv_area;
      const double wb = ((c.px - cx) * (a.py - cy) - (c.py - cy) * (a.px - cx)) * inv_area;
      const double wc = 1 - wa - wb;
      if (wa < 0 || wb < 0 || wc < 0) continue;
      const double qa = wa / a.depth, qb = wb / b.depth, qc = wc / c.depth, q = qa + qb + qc;
      const double z = 1 / q;
      float& stored = canvas.depth_at(px, py);
      if (!(z * (1 - 1e-4) < stored)) continue;
      stored = float(z);
      canvas.put(px, py, shade(qa * z, qb * z, qc * z));
    }
  return true;
}

}  // namespace kit
