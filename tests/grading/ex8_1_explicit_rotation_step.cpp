// ex 8.1: the cross-product matrix ω* and the lecture's explicit step R + h ω* R (rigid_rotation_step.hpp).
#include <cmath>

#include <Eigen/Geometry>
#include <kit_catch.hpp>

#include "cases.hpp"
#include "rigid_cases.hpp"
#include "rigid_rotation_step.hpp"

namespace {
using kit::Mat3;
using kit::Vec3;
using kit::test::largest_entry;
using kit::test::random_matrix;
using kit::test::random_rotation;
using kit::test::random_vector;

}  // namespace

TEST_CASE("ex 8.1: skew(w) a = w × a for random w and a, and skew(w) is the antisymmetric matrix of w",
          "[grade][08-rigid-bodies][ex8.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 w = random_vector(rng, 10), a = random_vector(rng, 10);
    const Mat3 s = kit::skew(w);
    INFO("trial " << trial << ": w = " << w.transpose() << ", a = " << a.transpose() << "\nskew(w) =\n" << s);
    // The product with a is the cross product (a transposed matrix gives a × w = −w × a).
    CHECK((s * a - w.cross(a)).norm() <= 1e-13 * w.norm() * a.norm());
    // Entry by entry: its entries are w's components, so they are exact.
    Mat3 expected;
    expected << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    CHECK(largest_entry(s - expected) == 0);
    // ω* ω = ω × ω = 0: the axis of the turn does not move.
    CHECK((s * w).norm() <= 1e-13 * w.squaredNorm());
  }
}

TEST_CASE("ex 8.1: one step is R + h ω* R, ω* on the left, for rotations and for R that have left them",
          "[grade][08-rigid-bodies][ex8.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 200; ++trial) {
    // Half the trials from a rotation, half from any matrix: the step is used on both once R drifts.
    const Mat3 r = trial % 2 == 0 ? random_rotation(rng) : random_matrix(rng);
    const Vec3 omega = random_vector(rng, 20);
    const double h = kit::test::uniform(rng, 1e-4, 0.1);
    // Column c of ω* R is ω × (column c of R): written with the cross product, not with a matrix.
    Mat3 expected;
    for (int c = 0; c < 3; ++c) expected.col(c) = r.col(c) + h * omega.cross(r.col(c));
    const Mat3 got = kit::explicit_rotation_step(r, omega, h);
    INFO("trial " << trial << ": h = " << h << " s, omega = " << omega.transpose() << " rad/s\nR =\n"
                  << r << "\ngot\n"
                  << got << "\nexpected R + h ω* R\n"
                  << expected);
    // R ω* (the product in the wrong order) misses by O(h|ω|), a renormalised R by O(h²|ω|²).
    CHECK(largest_entry(got - expected) <= 1e-14 * (1 + largest_entry(r)) * (1 + h * omega.norm()));
  }
}

TEST_CASE("ex 8.1: the step is not renormalised: from a rotation, det R grows to 1 + h²|ω|² in one step",
          "[grade][08-rigid-bodies][ex8.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 100; ++trial) {
    const Mat3 r = random_rotation(rng);
    const Vec3 omega = random_vector(rng, 20);
    const double h = kit::test::uniform(rng, 1e-2, 0.1);
    const Mat3 got = kit::explicit_rotation_step(r, omega, h);
    const double stretch = 1 + h * h * omega.squaredNorm();
    INFO("trial " << trial << ": h = " << h << " s, omega = " << omega.transpose() << " rad/s");
    // det (I + h ω*) = 1 + h²|ω|²: the lecture's step leaves SO(3), which is what chapter 8 shows.
    CHECK(got.determinant() == Approx(stretch).epsilon(1e-13));
    // RᵀR = I + h² (ω*)ᵀ ω* = (1 + h²|ω|²) I − h² ω ωᵀ seen in the body frame.
    const Vec3 axis = r.transpose() * omega;
    const Mat3 gram = stretch * Mat3::Identity() - h * h * axis * axis.transpose();
    CHECK(largest_entry(got.transpose() * got - gram) <= 1e-13 * stretch);
  }
}

TEST_CASE("ex 8.1: n steps at constant ω keep the axis and turn the plane across it by n·atan(h|ω|), "
          "stretched by (1 + h²|ω|²)^(n/2)",
          "[grade][08-rigid-bodies][ex8.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 50; ++trial) {
    const Mat3 r0 = random_rotation(rng);
    const Vec3 omega = random_vector(rng, 10);
    const double h = kit::test::uniform(rng, 1e-3, 0.05);
    const int n = std::uniform_int_distribution<int>(1, 200)(rng);
    // I + h ω* = n̂n̂ᵀ + s (cos φ (I − n̂n̂ᵀ) + sin φ n̂*), s = sqrt(1 + h²|ω|²), tan φ = h|ω|;
    // its n-th power is n̂n̂ᵀ + sⁿ (Rot(nφ, n̂) − n̂n̂ᵀ), Rot from Eigen's AngleAxis.
    const Vec3 axis = omega.normalized();
    const double s = std::sqrt(1 + h * h * omega.squaredNorm()), phi = std::atan(h * omega.norm());
    const Mat3 along = axis * axis.transpose();
    const Mat3 turn = Eigen::AngleAxisd(n * phi, axis).toRotationMatrix();
    const double grown = std::pow(s, n);
    const Mat3 expected = (along + grown * (turn - along)) * r0;
    Mat3 r = r0;
    r = kit::remote::iterated("explicit_rotation_step", n, r, omega, h);  // n steps, in the student's program
    INFO("trial " << trial << ": " << n << " steps of h = " << h << " s at omega = " << omega.transpose()
                  << " rad/s\ngot\n"
                  << r << "\nexpected\n"
                  << expected);
    CHECK(largest_entry(r - expected) <= 1e-12 * grown);
  }
}

TEST_CASE("ex 8.1: closed forms: h = 0 or ω = 0 give R; a quarter turn's first step about z",
          "[grade][08-rigid-bodies][ex8.1]") {
  auto rng = kit::test::random_engine();
  const Mat3 r = random_rotation(rng);
  CHECK(largest_entry(kit::explicit_rotation_step(r, Vec3(1, -2, 3), 0.0) - r) == 0);
  CHECK(largest_entry(kit::explicit_rotation_step(r, Vec3::Zero(), 0.1) - r) == 0);
  // From R = I at ω = 2 ẑ rad/s and h = 0.25 s: x̂ → x̂ + 0.5 ŷ and ŷ → ŷ − 0.5 x̂, z unchanged.
  Mat3 expected;
  expected << 1, -0.5, 0, 0.5, 1, 0, 0, 0, 1;
  const Mat3 got = kit::explicit_rotation_step(Mat3::Identity(), Vec3(0, 0, 2), 0.25);
  INFO("got\n" << got);
  CHECK(largest_entry(got - expected) <= 1e-15);
  // ω* on the left: from R = Rz(90°) at ω = x̂, the columns turn about the world x axis.
  Mat3 rz;
  rz << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  Mat3 left;  // rz + 0.5 x̂* rz, x̂* = [[0,0,0],[0,0,−1],[0,1,0]]
  left << 0, -1, 0, 1, 0, -0.5, 0.5, 0, 1;
  const Mat3 stepped = kit::explicit_rotation_step(rz, Vec3(1, 0, 0), 0.5);
  INFO("from Rz(90°) at omega = x, h = 0.5: got\n" << stepped);
  CHECK(largest_entry(stepped - left) <= 1e-15);
}
