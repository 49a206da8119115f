#include <kit/emitter.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kit {
namespace {
Vec3d cross(const Vec3d& a, const Vec3d& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3d normalised(const Vec3d& a) {
  const double n = std::hypot(a[0], a[1], a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}
// Two unit vectors that complete the unit `axis` to an orthonormal basis.
std::pair<Vec3d, Vec3d> basis_around(const Vec3d& axis) {
  const Vec3d helper = std::abs(axis[0]) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
  const Vec3d u = normalised(cross(axis, helper));
  return {u, cross(axis, u)};
}
float unit_clamped(double v) { return float(std::clamp(v, 0.0, 1.0)); }
}  // namespace

long emission_count(const Spread& rate, SpriteRandom& random) {
  const double n = std::max(draw(rate, random), 0.0);
  const double whole = std::floor(n);
  return long(whole) + (random.unit() < n - whole ? 1 : 0);
}

Vec3d direction_in_cap(const Vec3d& axis, double angle_deg, SpriteRandom& random) {
  // Archimedes: on the unit sphere, area is uniform in cos θ, so cos θ uniform gives a uniform cap.
  const double cos_max = std::cos(angle_deg * std::numbers::pi / 180.0);
  const double cos_t = 1.0 - random.unit() * (1.0 - cos_max);
  const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
  const double phi = 2.0 * std::numbers::pi * random.unit();
  const auto [u, w] = basis_around(axis);
  Vec3d d;
  for (int i = 0; i < 3; ++i) d[i] = cos_t * axis[i] + sin_t * (std::cos(phi) * u[i] + std::sin(phi) * w[i]);
  return d;
}

ParticleSpawn sample_particle(const Emitter& e, std::uint8_t index, SpriteRandom& random) {
  Vec3d offset{0, 0, 0}, direction = e.axis;
  switch (e.shape) {
    case EmitterShape::point:
      direction = direction_in_cap(e.axis, 180.0, random);
      break;
    case EmitterShape::disc: {  // r = R·√rand: uniform over the disc's area
      const auto [u, w] = basis_around(e.axis);
      const double r = e.radius * std::sqrt(random.unit()), phi = 2.0 * std::numbers::pi * random.unit();
      for (int i = 0; i < 3; ++i) offset[i] = r * (std::cos(phi) * u[i] + std::sin(phi) * w[i]);
      direction = direction_in_cap(e.axis, e.angle_deg, random);
      break;
    }
    case EmitterShape::sphere: {  // r = R·∛rand along a uniform direction: uniform in the ball
      direction = direction_in_cap(e.axis, 180.0, random);
      const double r = e.radius * std::cbrt(random.unit());
      for (int i = 0; i < 3; ++i) offset[i] = r * direction[i];
      break;
    }
    case EmitterShape::cone:
      direction = direction_in_cap(e.axis, e.angle_deg, random);
      break;
  }
  const double speed = draw(e.speed, random);
  ParticleSpawn p;
  p.x = float(e.position[0] + offset[0]), p.y = float(e.position[1] + offset[1]);
  p.z = float(e.position[2] + offset[2]);
  p.vx = float(speed * direction[0]), p.vy = float(speed * direction[1]), p.vz = float(speed * direction[2]);
  p.lifetime = float(draw(e.lifetime, random));
  p.size = float(std::max(draw(e.size, random), 0.0));
  p.r = unit_clamped(e.colour[0] + random.symmetric() * e.colour_variance[0]);
  p.g = unit_clamped(e.colour[1] + random.symmetric() * e.colour_variance[1]);
  p.b = unit_clamped(e.colour[2] + random.symmetric() * e.colour_variance[2]);
  p.alpha = unit_clamped(draw(e.alpha, random));
  p.emitter = index;
  return p;
}

}  // namespace kit
