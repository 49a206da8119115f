// The software rasteriser the 3D renderers share (raster.hpp).
#include <kit/render/raster.hpp>

namespace kit {
namespace {

constexpr Colour ground_light{0.70, 0.68, 0.63}, ground_dark{0.46, 0.44, 0.41};

// The fill light: from the side opposite the key (and a little from below the horizon's glow).
constexpr double fill_strength = 0.22;
const Vec3 fill_light = Vec3(0.6, 0.25, -0.35).normalized();
const Vec3 key_light = cloth_key_light.normalized();

// What the ray sees of the sky and the ground (draw_backdrop).
RayHit backdrop_hit(const Pinhole& camera, const Vec3& ray, const std::optional<double>& ground_height,
                    const ShadowTest& in_shadow) {
  const double inv_ray_length = 1 / ray.norm();
  RayHit hit{cloth_sky(ray.y() * inv_ray_length)};
  if (!ground_height || ray.y() == 0) return hit;
  // The ray's view-axis component is 1, so the parameter t along it is the depth.
  const Vec3 eye = camera.eye();
  const double t = (*ground_height - eye.y()) / ray.y();
  if (!(t >= Pinhole::near_depth)) return hit;
  const Vec3 p = eye + t * ray;
  const bool light_square =
      (long(std::floor(p.x() / ground_checker_square)) + long(std::floor(p.z() / ground_checker_square))) %
          2 ==
      0;
  // A pixel spans about t/F metres across (more at grazing angles); once a square is only a few
  // pixels wide the checker would alias, so it fades to its mean and then into the sky.
  const double footprint = t / camera.focal_px() / std::max(0.05, std::abs(ray.y()) * inv_ray_length);
  const double contrast = std::clamp(1.5 - 3 * footprint / ground_checker_square, 0.0, 1.0);
  const Colour ground = mix_colours(mix_colours(ground_light, ground_dark, 0.5),
                                    light_square ? ground_light : ground_dark, contrast);
  const double shade = in_shadow && in_shadow(p) ? cloth_ambient : light_intensity({0, 1, 0});
  const double haze = std::clamp(footprint / (4 * ground_checker_square), 0.0, 1.0);
  return {mix_colours(scale_colour(ground, shade), cloth_sky_bottom, haze), t};
}

}  // namespace

DepthCanvas::DepthCanvas(int width, int height, const Colour& fill)
    : image(width, height, fill),
      depth(std::size_t(width) * std::size_t(height), std::numeric_limits<float>::infinity()) {}

Vec3 key_light_direction() { return key_light; }

double light_intensity(const Vec3& unit_normal) {
  return std::min(1.0, cloth_ambient + (1 - cloth_ambient) * std::max(0.0, unit_normal.dot(key_light)) +
                           fill_strength * std::max(0.0, unit_normal.dot(fill_light)));
}

// Declared with the cloth's palette (cloth_renderer.hpp); defined here, next to the loop that
// calls it for every pixel, so that it is inlined there.
Colour cloth_sky(double elevation) {
  return mix_colours(cloth_sky_bottom, cloth_sky_top,
                     std::clamp(elevation / 0.5, 0.0, 1.0));  // sin 30° = 0.5
}

void draw_backdrop(const Pinhole& camera, const std::optional<double>& ground_height,
                   const ShadowTest& in_shadow, const RayForeground& in_front, DepthCanvas& canvas) {
  // Every pixel of every frame passes here. The loop is instantiated twice so that, without a
  // foreground, no call through a std::function sits in it: measured on chapter 6's flag scene
  // (sky only, 640 × 480), such a call, even skipped, made the whole frame take 9.5 ms, not 5.
  auto cast_every_ray = [&](auto&& foreground) {
    for (int py = 0; py < canvas.image.height; ++py)
      for (int px = 0; px < canvas.image.width; ++px) {
        const Vec3 ray = camera.ray(px + 0.5, py + 0.5);
        RayHit hit = backdrop_hit(camera, ray, ground_height, in_shadow);
        foreground(ray, hit);
        canvas.put(px, py, hit.colour);
        canvas.depth_at(px, py) = float(hit.depth);
      }
  };
  if (in_front)
    cast_every_ray(in_front);
  else
    cast_every_ray([](const Vec3&, RayHit&) {});
}

std::optional<ScreenVertex> screen_vertex(const Pinhole& camera, const Vec3& point) {
  if (!point.allFinite()) return std::nullopt;
  const auto p = camera.project(point.x(), point.y(), point.z());
  if (!p || !(std::abs(p->px) < max_pixel_coordinate) || !(std::abs(p->py) < max_pixel_coordinate))
    return std::nullopt;
  return ScreenVertex{p->px, p->py, p->depth};
}

}  // namespace kit
