#include <kit/render/camera.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include <Eigen/Geometry>  // cross()

#include <kit/base/usage.hpp>

namespace kit {
namespace {

// a·b summed left to right, as the pictures have always been drawn (vec3.hpp says why).
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

}  // namespace

Pinhole::Pinhole(const Camera& camera, int width, int height)
    : eye_(camera.position), width_(width), height_(height) {
  if (width < 1 || height < 1)
    throw std::invalid_argument(
        fmt::format("a camera image needs at least 1 x 1 pixels, not {} x {}", width, height));
  if (!(camera.fov_deg > 0 && camera.fov_deg < 180))
    throw UsageError(fmt::format("camera fov_deg must be in (0, 180) degrees, not {}", camera.fov_deg));
  const Vec3 view{camera.target[0] - eye_[0], camera.target[1] - eye_[1], camera.target[2] - eye_[2]};
  const double distance = std::sqrt(dot(view, view));
  if (!(distance > 0))
    throw UsageError("camera position and target coincide: the camera has no view direction");
  forward_ = view * (1 / distance);
  // Right is horizontal (forward × world up); looking straight up or down it is undefined, and
  // world x is taken instead.
  Vec3 right = forward_.cross(Vec3(0, 1, 0));
  const double length = std::sqrt(dot(right, right));
  right_ = length > 1e-9 ? Vec3(right * (1 / length)) : Vec3(1, 0, 0);
  up_ = right_.cross(forward_);
  focal_px_ = 0.5 * height / std::tan(0.5 * camera.fov_deg * std::numbers::pi / 180);
}

std::optional<Projected> Pinhole::project(double x, double y, double z) const {
  const Vec3 d{x - eye_[0], y - eye_[1], z - eye_[2]};
  const double depth = dot(d, forward_);
  if (!(depth >= near_depth)) return std::nullopt;
  const double scale = focal_px_ / depth;
  return Projected{0.5 * width_ + scale * dot(d, right_), 0.5 * height_ - scale * dot(d, up_), depth};
}

Vec3 Pinhole::ray(double px, double py) const {
  const double a = (px - 0.5 * width_) / focal_px_, b = (0.5 * height_ - py) / focal_px_;
  return {forward_[0] + a * right_[0] + b * up_[0], forward_[1] + a * right_[1] + b * up_[1],
          forward_[2] + a * right_[2] + b * up_[2]};
}

}  // namespace kit
