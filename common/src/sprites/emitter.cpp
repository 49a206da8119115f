#include <kit/sprites/emitter.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>  // cross()

namespace kit {
namespace {
Vec3 normalised(const Vec3& a) {
  const double n = std::hypot(a[0], a[1], a[2]);
  return {a[0] / n, a[1] / n, a[2] / n};
}
// Two unit vectors that complete the unit `axis` to an orthonormal basis.
std::pair<Vec3, Vec3> basis_around(const Vec3& axis) {
  const Vec3 helper = std::abs(axis[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 u = normalised(axis.cross(helper));
  return {u, axis.cross(u)};
}
}  // namespace

long emission_count(const Spread& rate, Random& random) {
  const double n = std::max(draw(rate, random), 0.0);
  const double whole = std::floor(n);
  return long(whole) + (random.unit() < n - whole ? 1 : 0);
}

Vec3 direction_in_cap(const Vec3& axis, double angle_deg, Random& random) {
  // Archimedes: on the unit sphere, area is uniform in cos θ, so cos θ uniform gives a uniform cap.
  const double cos_max = std::cos(angle_deg * std::numbers::pi / 180.0);
  const double cos_t = 1.0 - random.unit() * (1.0 - cos_max);
  const double sin_t = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
  const double phi = 2.0 * std::numbers::pi * random.unit();
  const auto [u, w] = basis_around(axis);
  Vec3 d;
  for (int i = 0; i < 3; ++i) d[i] = cos_t * axis[i] + sin_t * (std::cos(phi) * u[i] + std::sin(phi) * w[i]);
  return d;
}

Vec3 offset_in_disc(const Vec3& axis, double radius, Random& random) {
  const auto [u, w] = basis_around(axis);
  const double r = radius * std::sqrt(random.unit()), phi = 2.0 * std::numbers::pi * random.unit();
  Vec3 p;
  for (int i = 0; i < 3; ++i) p[i] = r * (std::cos(phi) * u[i] + std::sin(phi) * w[i]);
  return p;
}

BallPoint point_in_ball(double radius, Random& random) {
  const Vec3 d = direction_in_cap({0, 1, 0}, 180.0, random);
  const double r = radius * std::cbrt(random.unit());
  return {{r * d[0], r * d[1], r * d[2]}, d};
}

}  // namespace kit
