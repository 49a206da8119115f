// The rigid body renderer and its default camera (rigid_renderer.hpp).
#include <kit/rigid/rigid_renderer.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include <kit/render/raster.hpp>
#include <kit/rigid/rigid_mesh.hpp>

namespace kit {
namespace {

// Saturated enough to tell the parts apart under any light, and none close to the ground's greys.
constexpr std::array<Colour, 4> part_colours{
    {{0.90, 0.52, 0.24}, {0.30, 0.52, 0.86}, {0.36, 0.70, 0.40}, {0.62, 0.62, 0.66}}};
constexpr double camera_fov_deg = 40;        // vertical [deg]
constexpr double camera_azimuth_deg = 25;    // to the right of +z, seen from above [deg]
constexpr double camera_elevation_deg = 20;  // above the horizontal [deg]
constexpr double camera_margin = 1.05;       // the region's sphere fills 95 % of the narrower field
constexpr double smallest_region = 0.1;      // [m] a body with no size still gets a view

double degrees_to_radians(double degrees) { return degrees * std::numbers::pi / 180; }

// A radius about the centre of mass within which every part lies whatever the orientation [m]:
// the farthest corner of each part is at most |centre| + |sides|/2 away.
double bounding_radius(const RigidShape& shape) {
  double radius = 0;
  for (const BoxPart& part : shape.parts)
    radius = std::max(radius, part.centre.norm() + 0.5 * part.sides.norm());
  return radius;
}

// The body's shadow on the ground: whether the ray p + t l, t ≥ 0, from a ground point p towards
// the key light l meets a part. In the body frame, c = R⁻¹ (p − x) (R⁻¹ and not Rᵀ: explicit
// Euler's R drifts off the rotations), each part is an axis-aligned box, met by the slab test;
// the bounding sphere rejects most rays first.
class BodyShadow {
 public:
  BodyShadow(const RigidShape& shape, const RigidState& state)
      : shape_(shape), x_(state.x), radius_(bounding_radius(shape)) {
    const double determinant = state.R.determinant();
    casts_ = !shape.parts.empty() && state.x.allFinite() && std::isfinite(determinant) &&
             std::abs(determinant) > 1e-12;
    if (!casts_) return;
    to_body_ = state.R.inverse();
    light_ = to_body_ * key_light_direction();
  }
  // Whether there is a body to cast a shadow (a finite position and an invertible R).
  bool casts() const { return casts_; }

  bool operator()(const Vec3& ground_point) const {
    const Vec3 origin = to_body_ * (ground_point - x_);
    // |o + t d|² = r² has a root t ≥ 0 unless the ray misses the sphere or starts outside it
    // (c > 0) going away (o·d > 0).
    const double a = light_.squaredNorm(), half_b = origin.dot(light_);
    const double c = origin.squaredNorm() - radius_ * radius_;
    if (half_b * half_b - a * c < 0 || (c > 0 && half_b > 0)) return false;
    return std::any_of(shape_.parts.begin(), shape_.parts.end(),
                       [&](const BoxPart& part) { return meets(part, origin - part.centre); });
  }

 private:
  // The slab test: the ray from `from` (relative to the part's centre) along light_ is inside
  // all three slabs |c_i| ≤ sides_i / 2 over a common interval of t ≥ 0.
  bool meets(const BoxPart& part, const Vec3& from) const {
    double t_enter = 0, t_leave = std::numeric_limits<double>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      const double half = 0.5 * part.sides[axis];
      if (light_[axis] == 0) {
        if (std::abs(from[axis]) > half) return false;
        continue;
      }
      double t0 = (-half - from[axis]) / light_[axis], t1 = (half - from[axis]) / light_[axis];
      if (t0 > t1) std::swap(t0, t1);
      t_enter = std::max(t_enter, t0), t_leave = std::min(t_leave, t1);
      if (t_enter > t_leave) return false;
    }
    return true;
  }

  const RigidShape& shape_;
  Vec3 x_;
  Mat3 to_body_ = Mat3::Identity();
  Vec3 light_ = Vec3::UnitY();
  double radius_ = 0;
  bool casts_ = false;
};

}  // namespace

Colour rigid_part_colour(std::size_t part) { return part_colours[part % part_colours.size()]; }

Image render_rigid(const RigidShape& shape, const RigidState& state, const Camera& view, int width,
                   int height) {
  const Pinhole camera(view, width, height);
  DepthCanvas canvas(width, height, cloth_sky_top);
  const BodyShadow shadow(shape, state);
  ShadowTest in_shadow;
  if (shadow.casts()) in_shadow = [&shadow](const Vec3& p) { return shadow(p); };
  draw_backdrop(camera, 0.0, in_shadow, {}, canvas);  // the ground y = 0

  const Vec3 eye = camera.eye();
  for (const RigidFace& face : rigid_faces(shape, state)) {
    // A closed box hides the faces turned away from the eye behind the others: skipping them
    // halves the work. (False for a non-finite face too, which is not drawn.)
    if (!((face.corners[0] - eye).dot(face.normal) < 0)) continue;
    std::array<std::optional<ScreenVertex>, 4> screen;
    for (std::size_t k = 0; k < 4; ++k) screen[k] = screen_vertex(camera, face.corners[k]);
    if (!std::all_of(screen.begin(), screen.end(), [](const auto& vertex) { return vertex.has_value(); }))
      continue;
    const Colour colour = scale_colour(rigid_part_colour(face.part), light_intensity(face.normal));
    const auto flat = [&colour](double, double, double) { return colour; };
    fill_triangle(*screen[0], *screen[1], *screen[2], canvas, flat);
    fill_triangle(*screen[0], *screen[2], *screen[3], canvas, flat);
  }
  return std::move(canvas.image);
}

Camera rigid_camera(const RigidShape& shape, const std::vector<RigidState>& frames, bool with_ground,
                    double aspect) {
  if (frames.empty())
    throw std::invalid_argument("a rigid body's camera needs at least one frame to look at");
  if (!(aspect > 0) || !std::isfinite(aspect))
    throw std::invalid_argument(fmt::format("an image's aspect must be a positive number, not {}", aspect));
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (const RigidState& state : frames) {
    if (!state.x.allFinite())
      throw std::invalid_argument(fmt::format("a rigid body's camera cannot frame the centre ({}, {}, {})",
                                              state.x.x(), state.x.y(), state.x.z()));
    low = low.cwiseMin(state.x), high = high.cwiseMax(state.x);
  }
  const Vec3 reach = Vec3::Constant(bounding_radius(shape));
  low -= reach, high += reach;
  if (with_ground) low.y() = std::min(low.y(), 0.0);
  const Vec3 centre = 0.5 * (low + high);
  const double extent = std::max(0.5 * (high - low).norm(), smallest_region);
  // The narrower half field of view decides: tan(h/2) = aspect · tan(v/2).
  const double half_vertical = degrees_to_radians(camera_fov_deg / 2);
  const double half_field = std::min(half_vertical, std::atan(aspect * std::tan(half_vertical)));
  const double distance = camera_margin * extent / std::sin(half_field);
  const double azimuth = degrees_to_radians(camera_azimuth_deg),
               elevation = degrees_to_radians(camera_elevation_deg);
  const Vec3 towards_eye(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                         std::cos(azimuth) * std::cos(elevation));
  const Vec3 eye = centre + distance * towards_eye;
  return Camera{{eye.x(), eye.y(), eye.z()}, {centre.x(), centre.y(), centre.z()}, camera_fov_deg};
}

}  // namespace kit
