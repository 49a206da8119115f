// ex 8.4: the exponential map step exp(h ω*) R by Rodrigues' formula (rigid_exponential_map.hpp).
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <kit_catch.hpp>

#include "cases.hpp"
#include "rigid_cases.hpp"
#include "rigid_exponential_map.hpp"

namespace {
using kit::Mat3;
using kit::Vec3;
using kit::test::largest_entry;
using kit::test::random_rotation;

/// A direction drawn uniformly on the sphere.
Vec3 random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const double x = normal(rng), y = normal(rng), z = normal(rng);
  return Vec3(x, y, z).normalized();
}

/// The turn exp(θ n*) itself, from Eigen's angle-axis (not from Rodrigues written again).
Mat3 turn(double angle, const Vec3& axis) { return Eigen::AngleAxisd(angle, axis).toRotationMatrix(); }

double orthonormality(const Mat3& r) { return (r.transpose() * r - Mat3::Identity()).norm(); }
}  // namespace

TEST_CASE("ex 8.4: one step is AngleAxis(h|ω|, ω/|ω|) R, on the left, for θ = h|ω| from 1e-6 to 3 rad",
          "[grade][08-rigid-bodies][ex8.4]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const Mat3 r = random_rotation(rng);
    const Vec3 axis = random_direction(rng);
    const double speed = std::pow(10.0, kit::test::uniform(rng, -1, 2));                    // |ω| [rad/s]
    const double h = std::pow(10.0, kit::test::uniform(rng, -6, std::log10(3.0))) / speed;  // θ = h|ω|
    const Vec3 omega = speed * axis;
    const Mat3 expected = turn(h * omega.norm(), omega.normalized()) * r;
    const Mat3 got = kit::exponential_map_step(r, omega, h);
    INFO("trial " << trial << ": theta = h|omega| = " << h * omega.norm() << " rad about " << axis.transpose()
                  << "\nR =\n"
                  << r << "\ngot\n"
                  << got << "\nexpected\n"
                  << expected);
    // R exp(h ω*) (turning about the body axis ω instead of the world one) misses by O(θ).
    CHECK(largest_entry(got - expected) <= 2e-15);
    // One step adds only round-off to RᵀR − I (the random R itself is a few 1e-16 off SO(3)).
    CHECK(orthonormality(got) <= orthonormality(r) + 4e-15);
  }
}

TEST_CASE("ex 8.4: at constant ω, 1e5 steps stay on the rotations (|RᵀR − I| ≤ 1e-10) and turn by 1e5·h|ω|",
          "[grade][08-rigid-bodies][ex8.4]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 4; ++trial) {
    const Mat3 r0 = random_rotation(rng);
    const Vec3 axis = random_direction(rng);
    const double speed = std::pow(10.0, kit::test::uniform(rng, -1, 2));
    const double h = kit::test::uniform(rng, 0.01, 1.0) / speed;  // θ from 0.01 to 1 rad a step
    const Vec3 omega = speed * axis;
    const long n = 100'000;
    Mat3 r = r0;
    r = kit::remote::iterated("exponential_map_step", n, r, omega, h);  // n steps, in the student's program
    // The angle reduced to [−π, π] before it is handed to AngleAxis: n θ is up to 1e5 rad.
    const double angle = std::remainder(double(n) * (h * speed), 2 * std::acos(-1.0));
    const Mat3 expected = turn(angle, axis) * r0;
    INFO("trial " << trial << ": theta = " << h * speed << " rad a step, |RᵀR − I| = " << orthonormality(r)
                  << ", det R = " << r.determinant() << "\ngot\n"
                  << r << "\nexpected\n"
                  << expected);
    // A product of rotations is a rotation: the only drift is round-off, about 1e-16 a step (the
    // reference ends within 3e-11), where explicit Euler on R grows by (1 + θ²)^(n/2) and a
    // truncated series (I + θ n* + θ²/2 n*², say) by θ⁴/4 a step, 2.5e-9 or more.
    CHECK(orthonormality(r) <= 1e-10);
    CHECK(std::abs(r.determinant() - 1) <= 1e-10);
    CHECK(largest_entry(r - expected) <= 1e-9);
  }
}

TEST_CASE("ex 8.4: ω = 0 or h = 0 return R exactly, with no NaN from ω/|ω|",
          "[grade][08-rigid-bodies][ex8.4]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 20; ++trial) {
    const Mat3 r = random_rotation(rng);
    const Vec3 omega = 5 * random_direction(rng);
    const Mat3 still = kit::exponential_map_step(r, Vec3::Zero(), 0.01);
    const Mat3 no_time = kit::exponential_map_step(r, omega, 0.0);
    INFO("trial " << trial << ": omega = 0 gives\n"
                  << still << "\nh = 0 gives\n"
                  << no_time << "\nR =\n"
                  << r);
    CHECK(still.allFinite());
    CHECK(largest_entry(still - r) == 0);
    CHECK(no_time.allFinite());
    CHECK(largest_entry(no_time - r) == 0);
  }
}

TEST_CASE("ex 8.4: tiny turns are accurate: θ = 1e-12 to 1e-8 rad gives R + θ n* R to round-off",
          "[grade][08-rigid-bodies][ex8.4]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 60; ++trial) {
    const Mat3 r = random_rotation(rng);
    const Vec3 axis = random_direction(rng);
    const double theta = std::pow(10.0, -12.0 + 2.0 * (trial % 3));  // 1e-12, 1e-10, 1e-8 rad
    const double speed = std::pow(10.0, kit::test::uniform(rng, -3, 3));
    // To first order exp(θ n*) R = R + θ n* R; column c of n* R is n × (column c of R). The
    // second-order term θ²/2 is at most 5e-17: below the round-off of R's entries.
    Mat3 expected;
    for (int c = 0; c < 3; ++c) expected.col(c) = r.col(c) + theta * axis.cross(r.col(c));
    const Mat3 got = kit::exponential_map_step(r, speed * axis, theta / speed);
    INFO("trial " << trial << ": theta = " << theta << " rad, |omega| = " << speed << " rad/s\ngot − R\n"
                  << got - r << "\nexpected θ n* R\n"
                  << expected - r);
    // Returning R below some threshold misses by about θ: 1e-12 is a thousand times the tolerance.
    CHECK(got.allFinite());
    CHECK(largest_entry(got - expected) <= 1e-15);
  }
}

TEST_CASE("ex 8.4: large turns and the world frame: θ = 3 rad, π, 5 rad and 2π; a quarter turn about world x",
          "[grade][08-rigid-bodies][ex8.4]") {
  auto rng = kit::test::random_engine();
  const double pi = std::acos(-1.0);
  for (const double theta : {3.0, pi, 5.0, 2 * pi}) {
    const Mat3 r = random_rotation(rng);
    const Vec3 axis = random_direction(rng);
    const Mat3 got = kit::exponential_map_step(r, 2 * axis, theta / 2);
    INFO("theta = " << theta << " rad about " << axis.transpose() << "\ngot\n" << got);
    CHECK(largest_entry(got - turn(theta, axis) * r) <= 4e-15);
  }
  // Half a turn about z: exp(π ẑ*) = diag(−1, −1, 1), whatever R.
  const Mat3 r = random_rotation(rng);
  const Mat3 half = kit::exponential_map_step(r, Vec3(0, 0, pi), 1.0);
  CHECK(largest_entry(half - Vec3(-1, -1, 1).asDiagonal() * r) <= 1e-15);
  // From R = Rz(90°), ω = x̂ for h = π/2 s: Rx(90°) Rz(90°), the world's x axis. R Rx(90°) would
  // turn about R x̂ = ŷ instead.
  Mat3 rz, expected;
  rz << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  expected << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  const Mat3 got = kit::exponential_map_step(rz, Vec3(1, 0, 0), pi / 2);
  INFO("from Rz(90°), omega = x, h = pi/2: got\n" << got);
  CHECK(largest_entry(got - expected) <= 1e-15);
}
