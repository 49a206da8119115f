#include <kit/render/sprite_camera.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include <kit/base/usage.hpp>

namespace kit {
namespace {

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3d scaled(const Vec3d& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }

}  // namespace

SpriteCamera::SpriteCamera(const Camera& camera, int width, int height)
    : eye_(camera.position), width_(width), height_(height) {
  if (width < 1 || height < 1)
    throw std::invalid_argument(fmt::format("a camera image needs at least 1 x 1 pixels, not {} x {}", width, height));
  if (!(camera.fov_deg > 0 && camera.fov_deg < 180))
    throw UsageError(fmt::format("camera fov_deg must be in (0, 180) degrees, not {}", camera.fov_deg));
  const Vec3d view{camera.target[0] - eye_[0], camera.target[1] - eye_[1], camera.target[2] - eye_[2]};
  const double distance = std::sqrt(dot(view, view));
  if (!(distance > 0)) throw UsageError("camera position and target coincide: the camera has no view direction");
  forward_ = scaled(view, 1 / distance);
  // Right is horizontal (forward × world up); looking straight up or down it is undefined, and
  // world x is taken instead.
  Vec3d right = cross(forward_, {0, 1, 0});
  const double length = std::sqrt(dot(right, right));
  right_ = length > 1e-9 ? scaled(right, 1 / length) : Vec3d{1, 0, 0};
  up_ = cross(right_, forward_);
  focal_px_ = 0.5 * height / std::tan(0.5 * camera.fov_deg * std::numbers::pi / 180);
}

std::optional<Projected> SpriteCamera::project(double x, double y, double z) const {
  const Vec3d d{x - eye_[0], y - eye_[1], z - eye_[2]};
  const double depth = dot(d, forward_);
  if (!(depth >= near_depth)) return std::nullopt;
  const double scale = focal_px_ / depth;
  return Projected{0.5 * width_ + scale * dot(d, right_), 0.5 * height_ - scale * dot(d, up_), depth};
}

Vec3d SpriteCamera::ray(double px, double py) const {
  const double a = (px - 0.5 * width_) / focal_px_, b = (0.5 * height_ - py) / focal_px_;
  return {forward_[0] + a * right_[0] + b * up_[0], forward_[1] + a * right_[1] + b * up_[1],
          forward_[2] + a * right_[2] + b * up_[2]};
}

}  // namespace kit
