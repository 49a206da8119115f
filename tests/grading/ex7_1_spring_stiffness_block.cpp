// ex 7.1: the stiffness block ∂f_a/∂x_a of one cloth spring (cloth_jacobian.hpp).
#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <kit_catch.hpp>

#include "cases.hpp"
#include "cloth_jacobian.hpp"

namespace {
using kit::Mat3;
using kit::Vec3;

Vec3 random_vector(std::mt19937_64& rng, double scale) {
  return {kit::test::uniform(rng, -scale, scale), kit::test::uniform(rng, -scale, scale),
          kit::test::uniform(rng, -scale, scale)};
}

/// The spring force on end a, written from its potential: f_a = K (L0/l − 1) (x_a − x_b) [N].
Vec3 force_on_a(const Vec3& xa, const Vec3& xb, double rest, double k) {
  const Vec3 gap = xa - xb;
  return k * (rest / gap.norm() - 1.0) * gap;
}

/// ∂f_a/∂x_a by central differences, one column per axis of x_a.
Mat3 finite_difference_block(const Vec3& xa, const Vec3& xb, double rest, double k) {
  const double step = 1e-6 * (xa - xb).norm();
  Mat3 columns;
  for (int axis = 0; axis < 3; ++axis) {
    Vec3 ahead = xa, behind = xa;
    ahead[axis] += step;
    behind[axis] -= step;
    columns.col(axis) = (force_on_a(ahead, xb, rest, k) - force_on_a(behind, xb, rest, k)) / (2 * step);
  }
  return columns;
}

double largest_entry(const Mat3& m) { return m.cwiseAbs().maxCoeff(); }

/// A random spring: ends within a 4 m box, at least 5 cm apart, K over five decades.
struct RandomSpring {
  Vec3 xa, xb;
  double length, k;
};
RandomSpring random_spring(std::mt19937_64& rng) {
  RandomSpring s;
  do {
    s.xa = random_vector(rng, 2);
    s.xb = random_vector(rng, 2);
    s.length = (s.xa - s.xb).norm();
  } while (s.length < 0.05);
  s.k = std::pow(10.0, kit::test::uniform(rng, 0, 5));
  return s;
}
}  // namespace

TEST_CASE(
    "ex 7.1: without the clamp, the block is the derivative of f_a = −K (l − L0) x̂, stretched or compressed",
    "[grade][07-cloth-implicit][ex7.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const RandomSpring s = random_spring(rng);
    // Rest lengths from 0 (all stretch) to three times the length (strongly compressed).
    const double rest = s.length * kit::test::uniform(rng, 0, 3);
    const Mat3 expected = finite_difference_block(s.xa, s.xb, rest, s.k);
    const Mat3 got = kit::spring_stiffness_block(s.xa, s.xb, rest, s.k, false);
    INFO("trial " << trial << ": l = " << s.length << " m, L0 = " << rest << " m, K = " << s.k << " N/m");
    INFO("got\n" << got << "\nexpected (central differences)\n" << expected);
    CHECK(largest_entry(got - expected) <= 1e-6 * s.k * std::max(1.0, rest / s.length));
  }
}

TEST_CASE("ex 7.1: with the clamp, a stretched spring's block is still the exact derivative",
          "[grade][07-cloth-implicit][ex7.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const RandomSpring s = random_spring(rng);
    const double rest = s.length * kit::test::uniform(rng, 0, 0.999);  // l > L0: nothing to clamp
    const Mat3 expected = finite_difference_block(s.xa, s.xb, rest, s.k);
    const Mat3 got = kit::spring_stiffness_block(s.xa, s.xb, rest, s.k, true);
    INFO("trial " << trial << ": l = " << s.length << " m, L0 = " << rest << " m, K = " << s.k << " N/m");
    INFO("got\n" << got << "\nexpected (central differences)\n" << expected);
    CHECK(largest_entry(got - expected) <= 1e-6 * s.k);
  }
}

TEST_CASE("ex 7.1: compressed and clamped, the turn term is gone: the block is −K x̂x̂ᵀ",
          "[grade][07-cloth-implicit][ex7.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 200; ++trial) {
    const RandomSpring s = random_spring(rng);
    const double rest = s.length * kit::test::uniform(rng, 1.001, 4);  // l < L0
    // −K x̂x̂ᵀ entry by entry: −K d_r d_c / (d·d).
    const Vec3 d = s.xb - s.xa;
    Mat3 expected;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) expected(r, c) = -s.k * d[r] * d[c] / d.squaredNorm();
    const Mat3 got = kit::spring_stiffness_block(s.xa, s.xb, rest, s.k, true);
    INFO("trial " << trial << ": l = " << s.length << " m, L0 = " << rest << " m, K = " << s.k << " N/m");
    INFO("got\n" << got << "\nexpected\n" << expected);
    CHECK(largest_entry(got - expected) <= 1e-12 * s.k);
  }
}

TEST_CASE("ex 7.1: eigenvalues: −K along the spring, K (L0/l − 1) twice across it unclamped, 0 clamped",
          "[grade][07-cloth-implicit][ex7.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 200; ++trial) {
    const RandomSpring s = random_spring(rng);
    const double rest = s.length * kit::test::uniform(rng, 0, 3);
    const double across = s.k * (rest / s.length - 1);  // > 0 when compressed: the indefinite case
    INFO("trial " << trial << ": l = " << s.length << " m, L0 = " << rest << " m, K = " << s.k << " N/m");
    for (bool clamp : {false, true}) {
      const Mat3 got = kit::spring_stiffness_block(s.xa, s.xb, rest, s.k, clamp);
      const Eigen::SelfAdjointEigenSolver<Mat3> eigen(0.5 * (got + got.transpose()));
      // Expected, sorted: the axial −K, and the transverse value twice (clamped: at most 0).
      const double transverse = clamp ? std::min(across, 0.0) : across;
      const Eigen::Vector3d expected(-s.k, transverse, transverse);
      INFO("clamp = " << clamp << ", eigenvalues " << eigen.eigenvalues().transpose() << ", expected "
                      << expected.transpose());
      CHECK((eigen.eigenvalues() - expected).cwiseAbs().maxCoeff() <=
            1e-9 * s.k * std::max(1.0, rest / s.length));
    }
  }
}

TEST_CASE("ex 7.1: the block is symmetric, the same seen from b, unchanged by a translation, linear in K",
          "[grade][07-cloth-implicit][ex7.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 100; ++trial) {
    const RandomSpring s = random_spring(rng);
    const double rest = s.length * kit::test::uniform(rng, 0, 2);
    const Vec3 shift = random_vector(rng, 10);
    INFO("trial " << trial << ": l = " << s.length << " m, L0 = " << rest << " m, K = " << s.k << " N/m");
    for (bool clamp : {false, true}) {
      const Mat3 j = kit::spring_stiffness_block(s.xa, s.xb, rest, s.k, clamp);
      const double tol = 1e-12 * s.k * (1 + rest / s.length);
      INFO("clamp = " << clamp);
      CHECK(largest_entry(j - j.transpose()) <= tol);
      // ∂f_b/∂x_b = ∂f_a/∂x_a: swapping the ends gives the same block.
      CHECK(largest_entry(kit::spring_stiffness_block(s.xb, s.xa, rest, s.k, clamp) - j) <= tol);
      const Mat3 moved = kit::spring_stiffness_block(s.xa + shift, s.xb + shift, rest, s.k, clamp);
      CHECK(largest_entry(moved - j) <= 1e-9 * s.k * (1 + rest / s.length));
      CHECK(largest_entry(kit::spring_stiffness_block(s.xa, s.xb, rest, 3 * s.k, clamp) - 3 * j) <= 3 * tol);
    }
  }
}

TEST_CASE("ex 7.1: closed forms: L0 = 0 gives −K I; l = L0 gives −K x̂x̂ᵀ; zero length gives a zero block",
          "[grade][07-cloth-implicit][ex7.1]") {
  const double k = 250;
  // A zero-rest-length spring is linear, f_a = −K (x_a − x_b): its block is −K I in every direction.
  const Vec3 b(0.25, -1, 0.5);
  for (const Vec3& a : {Vec3(1, 2, 3), Vec3(-0.5, 0, 0), Vec3(0.25, -1, 4)}) {
    for (bool clamp : {false, true})
      CHECK(largest_entry(kit::spring_stiffness_block(a, b, 0.0, k, clamp) + k * Mat3::Identity()) <=
            1e-12 * k);
  }
  // At its rest length along y: only the yy entry, −K, with or without the clamp.
  Mat3 along_y = Mat3::Zero();
  along_y(1, 1) = -k;
  const Vec3 above = b + Vec3(0, 0.75, 0);
  for (bool clamp : {false, true})
    CHECK(largest_entry(kit::spring_stiffness_block(above, b, 0.75, k, clamp) - along_y) <= 1e-12 * k);
  // Half compressed along x (l = 1, L0 = 2), unclamped: −K on xx, +K across (K (L0/l − 1) = K).
  const Mat3 compressed = kit::spring_stiffness_block(Vec3(1, 0, 0), Vec3::Zero(), 2.0, k, false);
  CHECK(largest_entry(compressed - Vec3(-k, k, k).asDiagonal().toDenseMatrix()) <= 1e-12 * k);
  // Ends at the same point: no direction, no block, and nothing that is not a number.
  for (bool clamp : {false, true}) {
    const Mat3 j = kit::spring_stiffness_block(b, b, 0.5, k, clamp);
    CHECK(j.allFinite());
    CHECK(j.isZero(0));
  }
}
