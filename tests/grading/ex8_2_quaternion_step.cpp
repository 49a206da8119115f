// ex 8.2: one explicit Euler step of q' = ½ (0, ω) ⊗ q, then q / |q| (rigid_quaternion_step.hpp).
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <kit_catch.hpp>

#include "cases.hpp"
#include "rigid_cases.hpp"
#include "rigid_quaternion_step.hpp"

namespace {
using kit::Mat3;
using kit::Quat;
using kit::Vec3;
using kit::test::largest_entry;
using kit::test::random_unit_quaternion;
using kit::test::random_vector;

/// The lecture's step written by components: (0, ω) ⊗ (w, v) = (−ω·v, w ω + ω × v), so
/// q + h/2 (0, ω) ⊗ q = (w − h/2 ω·v, v + h/2 (w ω + ω × v)), then divided by its norm.
Quat expected_step(const Quat& q, const Vec3& omega, double h) {
  const double w = q.w() - 0.5 * h * omega.dot(q.vec());
  const Vec3 v = q.vec() + 0.5 * h * (q.w() * omega + omega.cross(q.vec()));
  const double norm = std::sqrt(w * w + v.squaredNorm());
  return Quat(w / norm, v.x() / norm, v.y() / norm, v.z() / norm);
}

double coefficient_gap(const Quat& a, const Quat& b) {
  return (a.coeffs() - b.coeffs()).cwiseAbs().maxCoeff();
}
}  // namespace

TEST_CASE("ex 8.2: one step is (q + h/2 (0, ω) ⊗ q) / |…| for random unit q, ω and h",
          "[grade][08-rigid-bodies][ex8.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const Quat q = random_unit_quaternion(rng);
    const Vec3 omega = random_vector(rng, 20);
    const double h = kit::test::uniform(rng, 1e-4, 0.1);
    const Quat got = kit::quaternion_step(q, omega, h);
    const Quat expected = expected_step(q, omega, h);
    INFO("trial " << trial << ": q = " << q.coeffs().transpose()
                  << " (x, y, z, w), omega = " << omega.transpose() << " rad/s, h = " << h << " s\ngot      "
                  << got.coeffs().transpose() << "\nexpected " << expected.coeffs().transpose());
    // Without the ½ the step is twice as long; q ⊗ (0, ω) flips the sign of ω × v; without the
    // division |q| = sqrt(1 + h²|ω|²/4): each misses by far more than round-off.
    CHECK(coefficient_gap(got, expected) <= 1e-14);
  }
}

TEST_CASE("ex 8.2: the step is normalised: |q| = 1 after every one of 1e4 steps, even at h|ω| = 10",
          "[grade][08-rigid-bodies][ex8.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 5; ++trial) {
    Quat q = random_unit_quaternion(rng);
    const Vec3 omega = random_vector(rng, 1).normalized() * std::pow(10.0, kit::test::uniform(rng, -2, 1));
    const double h = trial == 0 ? 10.0 / omega.norm() : kit::test::uniform(rng, 1e-3, 1);
    double worst = 0;
    for (const Quat& step :
         kit::remote::iterate("quaternion_step", 10'000, q, omega, h))  // in the student's program
      worst = std::max(worst, std::abs(step.norm() - 1));
    INFO("trial " << trial << ": h|omega| = " << h * omega.norm() << ", largest | |q| − 1 | " << worst);
    CHECK(worst <= 1e-15);
  }
}

TEST_CASE("ex 8.2: at constant ω, n steps turn q by exactly n·2·atan(h|ω|/2) about ω, in the world frame",
          "[grade][08-rigid-bodies][ex8.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 100; ++trial) {
    const Quat q0 = random_unit_quaternion(rng);
    const Vec3 omega = random_vector(rng, 10);
    const double h = kit::test::uniform(rng, 1e-3, 0.2);
    const int n = std::uniform_int_distribution<int>(1, 1000)(rng);
    // 1 + h/2 (0, ω) = sqrt(1 + h²|ω|²/4) (cos α, sin α ω/|ω|) with tan α = h|ω|/2: once normalised,
    // a turn by 2α about ω, applied on the left (world frame). n steps turn by 2nα.
    const double angle = 2.0 * n * std::atan(0.5 * h * omega.norm());
    const Mat3 expected =
        Eigen::AngleAxisd(angle, omega.normalized()).toRotationMatrix() * q0.toRotationMatrix();
    Quat q = q0;
    q = kit::remote::iterated("quaternion_step", n, q, omega, h);  // n steps, in the student's program
    const Mat3 got = q.toRotationMatrix();
    INFO("trial " << trial << ": " << n << " steps of h = " << h << " s at omega = " << omega.transpose()
                  << " rad/s, |q| = " << q.norm() << "\ngot\n"
                  << got << "\nexpected\n"
                  << expected);
    CHECK(largest_entry(got - expected) <= 1e-11);
    CHECK(std::abs(q.norm() - 1) <= 1e-15);
  }
}

TEST_CASE("ex 8.2: ω is in the world frame: (0, ω) ⊗ q turns about the world axis, q ⊗ (0, ω) would not",
          "[grade][08-rigid-bodies][ex8.2]") {
  // q0 = a quarter turn about z; ω = x̂ rad/s (world). The world-frame step turns about x, the
  // body-frame one about q0's image of x, which is the world y axis.
  const Quat q0(Eigen::AngleAxisd(std::acos(0.0), Vec3::UnitZ()));
  const double h = 0.1, angle = 2 * std::atan(0.05);
  const Mat3 world = Eigen::AngleAxisd(angle, Vec3::UnitX()).toRotationMatrix() * q0.toRotationMatrix();
  const Mat3 body = q0.toRotationMatrix() * Eigen::AngleAxisd(angle, Vec3::UnitX()).toRotationMatrix();
  const Mat3 got = kit::quaternion_step(q0, Vec3::UnitX(), h).toRotationMatrix();
  INFO("got\n" << got << "\nworld frame (expected)\n" << world << "\nbody frame\n" << body);
  CHECK(largest_entry(got - world) <= 1e-15);
  CHECK(largest_entry(got - body) > 0.05);  // the two differ by about the step's angle, 0.0999 rad
}

TEST_CASE("ex 8.2: closed forms: ω = 0 or h = 0 leave q; h|ω| = 2 from the identity is a quarter turn",
          "[grade][08-rigid-bodies][ex8.2]") {
  auto rng = kit::test::random_engine();
  const Quat q = random_unit_quaternion(rng);
  CHECK(coefficient_gap(kit::quaternion_step(q, Vec3::Zero(), 0.1), q) <= 4e-16);
  CHECK(coefficient_gap(kit::quaternion_step(q, Vec3(3, -1, 2), 0.0), q) <= 4e-16);
  // From (1, 0) at ω = 2 ẑ rad/s over h = 1 s: (1, 0, 0, 1)/√2, 2·atan(1) = π/2 about z.
  const Quat got = kit::quaternion_step(Quat::Identity(), Vec3(0, 0, 2), 1.0);
  INFO("got " << got.coeffs().transpose() << " (x, y, z, w)");
  CHECK(std::abs(got.w() - std::sqrt(0.5)) <= 4e-16);
  CHECK(std::abs(got.z() - std::sqrt(0.5)) <= 4e-16);
  CHECK(got.vec().head<2>().norm() == 0);
  // From the identity at ω = −2 x̂ rad/s over h = 0.5 s: (1, −0.5, 0, 0)/sqrt(1.25), the step's sign of ω.
  const Quat back = kit::quaternion_step(Quat::Identity(), Vec3(-2, 0, 0), 0.5);
  INFO("got " << back.coeffs().transpose() << " (x, y, z, w)");
  CHECK(std::abs(back.w() - 1 / std::sqrt(1.25)) <= 1e-15);
  CHECK(std::abs(back.x() + 0.5 / std::sqrt(1.25)) <= 1e-15);
}
