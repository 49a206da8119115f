// ex 7.3: Baraff & Witkin's filtered preconditioned conjugate gradient (cloth_pcg.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <kit_catch.hpp>

#include "cases.hpp"
#include "cloth_pcg.hpp"

namespace {
using kit::Mat3;
using kit::Vec3;

long random_index(std::mt19937_64& rng, long n) { return std::uniform_int_distribution<long>(0, n - 1)(rng); }

Vec3 random_unit(std::mt19937_64& rng) {
  Vec3 u;
  do {
    u = Vec3(kit::test::uniform(rng, -1, 1), kit::test::uniform(rng, -1, 1), kit::test::uniform(rng, -1, 1));
  } while (u.norm() < 0.1 || u.norm() > 1);
  return u / u.norm();
}

/// Per node: free (S = I), pinned (S = 0) or held on a plane of normal n (S = I − nnᵀ).
enum class Kind { free, pinned, plane };
struct Constraints {
  std::vector<Kind> kind;
  std::vector<Vec3> normal;  // of the plane nodes
  std::vector<Mat3> filters;
  long dofs = 0;  // the dimension of the directions the nodes may move in
};

Constraints make_constraints(const std::vector<Kind>& kind, std::mt19937_64& rng) {
  Constraints c;
  c.kind = kind;
  for (Kind k : kind) {
    const Vec3 n = random_unit(rng);
    c.normal.push_back(n);
    if (k == Kind::free) c.filters.push_back(Mat3::Identity()), c.dofs += 3;
    if (k == Kind::pinned) c.filters.push_back(Mat3::Zero());
    if (k == Kind::plane) c.filters.push_back(Mat3::Identity() - n * n.transpose()), c.dofs += 2;
  }
  return c;
}

/// A random mix: at least one free node, then about half free, a fifth pinned, the rest on planes.
Constraints random_constraints(std::mt19937_64& rng, long nodes) {
  std::vector<Kind> kind(std::size_t(nodes), Kind::free);
  for (long i = 1; i < nodes; ++i) {
    const double u = kit::test::uniform(rng, 0, 1);
    kind[std::size_t(i)] = u < 0.5 ? Kind::free : u < 0.7 ? Kind::pinned : Kind::plane;
  }
  std::shuffle(kind.begin(), kind.end(), rng);
  return make_constraints(kind, rng);
}

/// An orthonormal basis Z (3n × dofs) of the allowed directions: x = Z y for every admissible x.
Eigen::MatrixXd allowed_basis(const Constraints& c) {
  const long nodes = long(c.kind.size());
  Eigen::MatrixXd z = Eigen::MatrixXd::Zero(3 * nodes, c.dofs);
  long column = 0;
  for (long i = 0; i < nodes; ++i) {
    if (c.kind[std::size_t(i)] == Kind::free)
      for (int axis = 0; axis < 3; ++axis) z(3 * i + axis, column++) = 1;
    if (c.kind[std::size_t(i)] == Kind::plane) {
      const Vec3& n = c.normal[std::size_t(i)];
      const Vec3 seed = std::abs(n[0]) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
      const Vec3 u = n.cross(seed).normalized(), w = n.cross(u);
      z.block<3, 1>(3 * i, column++) = u;
      z.block<3, 1>(3 * i, column++) = w;
    }
  }
  return z;
}

/// S w, node by node, written with the basis: S = Z Zᵀ.
Eigen::VectorXd project(const Eigen::MatrixXd& z, const Eigen::VectorXd& w) {
  return z * (z.transpose() * w);
}

/// The constrained solution by a dense Cholesky of Zᵀ A Z: x = Z (Zᵀ A Z)⁻¹ Zᵀ b.
Eigen::VectorXd constrained_solution(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                                     const Eigen::MatrixXd& z) {
  const Eigen::MatrixXd reduced = z.transpose() * a * z;
  return z * reduced.llt().solve(z.transpose() * b);
}

/// A random SPD matrix of `nodes` nodes: a positive diagonal plus 4 per row of random rank-one
/// couplings (each positive semidefinite), then scaled on both sides by 10^[−spread, spread].
Eigen::MatrixXd random_spd(std::mt19937_64& rng, long nodes, double spread) {
  const long size = 3 * nodes;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(size, size);
  for (long i = 0; i < size; ++i) a(i, i) = kit::test::uniform(rng, 0.5, 2);
  for (long coupling = 0; coupling < 2 * size; ++coupling) {
    const long p = random_index(rng, size);
    long q = random_index(rng, size - 1);
    if (q >= p) ++q;
    const Eigen::Vector2d w(kit::test::uniform(rng, -1, 1), kit::test::uniform(rng, -1, 1));
    const Eigen::Matrix2d outer = w * w.transpose();
    a(p, p) += outer(0, 0), a(q, q) += outer(1, 1), a(p, q) += outer(0, 1), a(q, p) += outer(1, 0);
  }
  const Eigen::VectorXd scale = Eigen::VectorXd::NullaryExpr(
      size, [&] { return std::pow(10.0, kit::test::uniform(rng, -spread, spread)); });
  return scale.asDiagonal() * a * scale.asDiagonal();
}

Eigen::VectorXd random_vector(std::mt19937_64& rng, long size) {
  return Eigen::VectorXd::NullaryExpr(size, [&] { return kit::test::uniform(rng, -1, 1); });
}

kit::SparseMatrix sparse(const Eigen::MatrixXd& dense) { return dense.sparseView(); }

/// A small cloth's matrix, built here: an nx × ny grid of 10 cm cells, jittered, m = 5 g a node,
/// structural and shear springs K = 800 N/m, μ = 0.05 N·s/m, h = 10 ms, clamped stiffness:
/// each spring adds h μ x̂x̂ᵀ + h² K [x̂x̂ᵀ + s (I − x̂x̂ᵀ)], s = max(0, 1 − L0/l), with the
/// usual signs (+ on the diagonal blocks, − off them).
Eigen::MatrixXd cloth_matrix(std::mt19937_64& rng, int nx, int ny) {
  const long nodes = long(nx) * ny;
  std::vector<Vec3> p;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      p.emplace_back(0.1 * i + kit::test::uniform(rng, -0.01, 0.01), kit::test::uniform(rng, -0.01, 0.01),
                     0.1 * j + kit::test::uniform(rng, -0.01, 0.01));
  const double m = 0.005, k = 800, mu = 0.05, h = 0.01;
  Eigen::MatrixXd a = m * Eigen::MatrixXd::Identity(3 * nodes, 3 * nodes);
  const auto join = [&](long s, long t, double rest) {
    const Vec3 d = p[std::size_t(s)] - p[std::size_t(t)];
    const double length = d.norm();
    const Mat3 axial = d * d.transpose() / (length * length);
    const double turn = std::max(0.0, 1 - rest / length);
    const Mat3 block = (h * mu + h * h * k) * axial + h * h * k * turn * (Mat3::Identity() - axial);
    a.block<3, 3>(3 * s, 3 * s) += block;
    a.block<3, 3>(3 * t, 3 * t) += block;
    a.block<3, 3>(3 * s, 3 * t) -= block;
    a.block<3, 3>(3 * t, 3 * s) -= block;
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const long at = long(j) * nx + i;
      if (i + 1 < nx) join(at, at + 1, 0.1);
      if (j + 1 < ny) join(at, at + nx, 0.1);
      if (i + 1 < nx && j + 1 < ny) join(at, at + nx + 1, 0.1 * std::sqrt(2.0));
      if (i > 0 && j + 1 < ny) join(at, at + nx - 1, 0.1 * std::sqrt(2.0));
    }
  return a;
}

/// What a constrained solve must satisfy, checked in one place (a fixed number of assertions).
void check_constrained_solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const Constraints& c,
                             double tol, const kit::PcgResult& got) {
  const Eigen::MatrixXd z = allowed_basis(c);
  REQUIRE(got.x.size() == b.size());
  CHECK(got.x.allFinite());
  CHECK(got.converged);
  CHECK_FALSE(got.negative_curvature);
  // The true residual, recomputed: ‖S(b − A x)‖ ≤ tol ‖S b‖ (a little slack for the drift of the
  // recursively updated residual), and the reported one says the same.
  const double filtered_b = project(z, b).norm();
  const double true_ratio = project(z, b - a * got.x).norm() / filtered_b;
  INFO("iterations " << got.iterations << ", reported residual " << got.residual << ", true " << true_ratio);
  CHECK(true_ratio <= 1.5 * tol);
  CHECK(std::abs(got.residual - true_ratio) <= 0.5 * tol);
  // Constraints hold exactly: pinned nodes do not move at all, plane nodes not along n.
  double pinned = 0, normal = 0;
  for (std::size_t i = 0; i < c.kind.size(); ++i) {
    const Vec3 xi = got.x.segment<3>(3 * Eigen::Index(i));
    if (c.kind[i] == Kind::pinned) pinned = std::max(pinned, xi.cwiseAbs().maxCoeff());
    if (c.kind[i] == Kind::plane) normal = std::max(normal, std::abs(c.normal[i].dot(xi)));
  }
  CHECK(pinned == 0);
  CHECK(normal <= 1e-12 * (got.x.cwiseAbs().maxCoeff() + 1e-300));
  // Against the constrained solution by a dense factorisation, and within the dimension of the
  // problem (conjugate gradient terminates in at most that many steps in exact arithmetic; two more for
  // round-off). The error bound of a residual: |x − x_exact| ≤ cond(Zᵀ A Z) · (residual ratio) · |x_exact|.
  const Eigen::VectorXd exact = constrained_solution(a, b, z);
  const Eigen::VectorXd spectrum =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(z.transpose() * a * z, Eigen::EigenvaluesOnly)
          .eigenvalues();
  const double condition = spectrum.maxCoeff() / spectrum.minCoeff();
  INFO("|x − x_exact| = " << (got.x - exact).norm() << ", |x_exact| = " << exact.norm() << ", dofs " << c.dofs
                          << ", condition " << condition);
  CHECK((got.x - exact).norm() <= (2 * condition * tol + 1e-12) * exact.norm());
  CHECK((got.iterations >= 1 && got.iterations <= c.dofs + 2));
}
}  // namespace

TEST_CASE("ex 7.3: random SPD systems with free, pinned and plane nodes: solved to the tolerance, "
          "constraints exact",
          "[grade][07-cloth-implicit][ex7.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 60; ++trial) {
    const long nodes = 1 + random_index(rng, 40);
    const Eigen::MatrixXd a = random_spd(rng, nodes, 0.5);
    const Constraints c = random_constraints(rng, nodes);
    const Eigen::VectorXd b = random_vector(rng, 3 * nodes);
    const double tol = std::pow(10.0, kit::test::uniform(rng, -10, -6));
    INFO("trial " << trial << ": " << nodes << " nodes, " << c.dofs << " free directions, tolerance " << tol);
    check_constrained_solve(a, b, c, tol,
                            kit::filtered_pcg(sparse(a), b, c.filters, tol, 10 * int(a.rows())));
  }
}

TEST_CASE("ex 7.3: a small cloth: two loaded corners pinned, an edge held on a plane",
          "[grade][07-cloth-implicit][ex7.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 10; ++trial) {
    const int nx = 6 + int(random_index(rng, 5)), ny = 4 + int(random_index(rng, 4));
    const Eigen::MatrixXd a = cloth_matrix(rng, nx, ny);
    std::vector<Kind> kind(std::size_t(nx * ny), Kind::free);
    kind[0] = kind[std::size_t(nx - 1)] = Kind::pinned;
    for (int j = 1; j < ny; ++j) kind[std::size_t(j * nx)] = Kind::plane;  // the left edge
    const Constraints c = make_constraints(kind, rng);
    // b = h (f + h ∂f/∂x v): here gravity on each node and a random push; the pinned corners
    // carry a load 10⁶ times larger, which the filter removes: the tolerance is relative to
    // ‖S b‖, never to ‖b‖.
    Eigen::VectorXd b = 0.05 * random_vector(rng, 3 * nx * ny);
    for (int i = 0; i < nx * ny; ++i) b[3 * i + 1] -= 0.01 * 0.005 * 9.81;
    b.head<3>() *= 1e6;
    b.segment<3>(3 * (nx - 1)) *= 1e6;
    INFO("trial " << trial << ": " << nx << " × " << ny << " nodes");
    check_constrained_solve(a, b, c, 1e-9, kit::filtered_pcg(sparse(a), b, c.filters, 1e-9, 1000));
  }
}

TEST_CASE("ex 7.3: identity filters give plain Jacobi-preconditioned CG: Eigen's ConjugateGradient agrees",
          "[grade][07-cloth-implicit][ex7.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 30; ++trial) {
    const long nodes = 2 + random_index(rng, 30);
    const Eigen::MatrixXd a = random_spd(rng, nodes, 1);
    const Eigen::VectorXd b = random_vector(rng, 3 * nodes);
    const kit::SparseMatrix matrix = sparse(a);
    const std::vector<Mat3> identity(std::size_t(nodes), Mat3::Identity());
    const double tol = 1e-10;
    const kit::PcgResult got = kit::filtered_pcg(matrix, b, identity, tol, 1000);
    // Eigen's CG, preconditioned by the diagonal too, with the same stopping rule ‖r‖ ≤ tol ‖b‖.
    Eigen::ConjugateGradient<kit::SparseMatrix, Eigen::Lower | Eigen::Upper> eigen_cg;
    eigen_cg.setTolerance(tol);
    eigen_cg.setMaxIterations(1000);
    eigen_cg.compute(matrix);
    const Eigen::VectorXd expected = eigen_cg.solve(b);
    REQUIRE(eigen_cg.info() == Eigen::Success);
    REQUIRE(got.x.size() == b.size());
    INFO("trial " << trial << ": " << nodes << " nodes; iterations " << got.iterations << ", Eigen's "
                  << eigen_cg.iterations() << " (it does not count its last product)");
    CHECK(got.converged);
    CHECK((got.x - expected).norm() <= 1e-7 * expected.norm());
    CHECK((b - a * got.x).norm() <= 1.5 * tol * b.norm());
    // The same iterates, so the same number of products, give or take the last one.
    CHECK(std::abs(got.iterations - int(eigen_cg.iterations() + 1)) <= 1);
  }
}

TEST_CASE("ex 7.3: preconditioned by diag(A): a system scaled over 8 decades takes the iterations of the "
          "unscaled one",
          "[grade][07-cloth-implicit][ex7.3]") {
  // With E diagonal, diag(E A E) = E diag(A) E: the preconditioned iterates of (E A E) y = E b
  // are those of A x = b, y = E⁻¹ x. Unpreconditioned CG would need far more on E A E.
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 10; ++trial) {
    const long nodes = 30;
    const Eigen::MatrixXd a = random_spd(rng, nodes, 0);
    const Eigen::VectorXd e = Eigen::VectorXd::NullaryExpr(
        3 * nodes, [&] { return std::pow(10.0, kit::test::uniform(rng, -2, 2)); });
    const Eigen::MatrixXd scaled = e.asDiagonal() * a * e.asDiagonal();
    const Eigen::VectorXd b = random_vector(rng, 3 * nodes);
    const std::vector<Mat3> identity(std::size_t(nodes), Mat3::Identity());
    const kit::PcgResult plain = kit::filtered_pcg(sparse(a), b, identity, 1e-8, 1000);
    const kit::PcgResult hard = kit::filtered_pcg(sparse(scaled), e.asDiagonal() * b, identity, 1e-8, 1000);
    INFO("trial " << trial << ": iterations " << plain.iterations << " unscaled, " << hard.iterations
                  << " scaled");
    CHECK(plain.converged);
    CHECK(hard.converged);
    CHECK(hard.iterations <= plain.iterations + 2);
  }
}

TEST_CASE(
    "ex 7.3: max_iterations caps the products: one is one exact PCG step, then it reports no convergence",
    "[grade][07-cloth-implicit][ex7.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 20; ++trial) {
    const long nodes = 10 + random_index(rng, 20);
    const Eigen::MatrixXd a = random_spd(rng, nodes, 1);
    const Constraints c = random_constraints(rng, nodes);
    const Eigen::MatrixXd z = allowed_basis(c);
    const Eigen::VectorXd b = random_vector(rng, 3 * nodes);
    const kit::SparseMatrix matrix = sparse(a);
    INFO("trial " << trial << ": " << nodes << " nodes, " << c.dofs << " free directions");
    // One step from x = 0: direction d = S diag(A)⁻¹ S b, length (S b · d) / (d · A d).
    const Eigen::VectorXd sb = project(z, b);
    const Eigen::VectorXd d = project(z, sb.cwiseQuotient(a.diagonal()));
    const Eigen::VectorXd one_step = (sb.dot(d) / d.dot(a * d)) * d;
    const kit::PcgResult once = kit::filtered_pcg(matrix, b, c.filters, 1e-12, 1);
    REQUIRE(once.x.size() == b.size());
    CHECK(once.iterations == 1);
    CHECK_FALSE(once.converged);
    CHECK((once.x - one_step).norm() <= 1e-12 * one_step.norm());
    // A few steps: exactly that many products, the residual reported is the true one, above tol.
    const int cap = 2 + int(random_index(rng, 3));
    const kit::PcgResult few = kit::filtered_pcg(matrix, b, c.filters, 1e-12, cap);
    const double true_ratio = project(z, b - a * few.x).norm() / sb.norm();
    CHECK(few.iterations == cap);
    CHECK_FALSE(few.converged);
    CHECK_FALSE(few.negative_curvature);
    CHECK(few.residual == Approx(true_ratio).epsilon(1e-6));
    CHECK(few.residual > 1e-12);
    // None at all: x stays 0.
    const kit::PcgResult none = kit::filtered_pcg(matrix, b, c.filters, 1e-12, 0);
    CHECK(none.iterations == 0);
    CHECK(none.x.size() == b.size());
    CHECK(none.x.isZero(0));
    CHECK_FALSE(none.converged);
  }
}

TEST_CASE(
    "ex 7.3: nothing to solve (b = 0, or b only on pinned nodes): x = 0, residual 0, no product, converged",
    "[grade][07-cloth-implicit][ex7.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 10; ++trial) {
    const long nodes = 3 + random_index(rng, 10);
    const Eigen::MatrixXd a = random_spd(rng, nodes, 1);
    std::vector<Kind> kind(std::size_t(nodes), Kind::free);
    kind[0] = kind[2] = Kind::pinned;
    kind[1] = Kind::plane;
    const Constraints c = make_constraints(kind, rng);
    Eigen::VectorXd only_pins = Eigen::VectorXd::Zero(3 * nodes);
    only_pins.head<3>() = Vec3(1, -2, 3);
    only_pins.segment<3>(6) = Vec3(-4, 0.5, 2);
    for (const Eigen::VectorXd& b : {Eigen::VectorXd(Eigen::VectorXd::Zero(3 * nodes)), only_pins}) {
      const kit::PcgResult got = kit::filtered_pcg(sparse(a), b, c.filters, 1e-10, 100);
      INFO("trial " << trial << ", |b| = " << b.norm());
      REQUIRE(got.x.size() == b.size());
      CHECK(got.x.isZero(0));
      CHECK(got.iterations == 0);
      CHECK(got.residual == 0);
      CHECK(got.converged);
      CHECK_FALSE(got.negative_curvature);
    }
  }
}

TEST_CASE("ex 7.3: where cᵀAc ≤ 0 (A indefinite or singular) it stops, says so, and returns no NaN",
          "[grade][07-cloth-implicit][ex7.3]") {
  const long nodes = 4;
  const std::vector<Mat3> identity(std::size_t(nodes), Mat3::Identity());
  // x of node 0 and x of node 1 coupled by [[1, g], [g, 1]], the rest the identity; b = e_0 − e_3,
  // the first direction is b itself. g = 3: curvature 2 − 2g < 0 (indefinite); g = 1: exactly 0.
  for (double g : {3.0, 1.0}) {
    Eigen::MatrixXd a = Eigen::MatrixXd::Identity(3 * nodes, 3 * nodes);
    a(0, 3) = a(3, 0) = g;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * nodes);
    b[0] = 1, b[3] = -1;
    const kit::PcgResult got = kit::filtered_pcg(sparse(a), b, identity, 1e-10, 100);
    INFO("coupling " << g);
    REQUIRE(got.x.size() == b.size());
    CHECK(got.negative_curvature);
    CHECK_FALSE(got.converged);
    CHECK(got.iterations == 1);
    CHECK(got.x.isZero(0));  // no step along a direction of no curvature
    CHECK(got.residual == Approx(1.0));
  }
  // Random strongly indefinite matrices (positive diagonal, large couplings): it stops within
  // max_iterations, flags negative curvature and returns finite numbers.
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 20; ++trial) {
    const long size = 3 * (5 + random_index(rng, 20));
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(size, size);
    for (long i = 0; i < size; ++i) a(i, i) = kit::test::uniform(rng, 1, 2);
    for (long k = 0; k < 3 * size; ++k) {
      const long p = random_index(rng, size), q = random_index(rng, size);
      if (p != q) a(p, q) = a(q, p) = kit::test::uniform(rng, -4, 4);
    }
    const std::vector<Mat3> unfiltered(std::size_t(size / 3), Mat3::Identity());
    const Eigen::VectorXd b = random_vector(rng, size);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(a, Eigen::EigenvaluesOnly);
    INFO("trial " << trial << ": smallest eigenvalue " << spectrum.eigenvalues()[0]);
    REQUIRE(spectrum.eigenvalues()[0] < -1);
    const kit::PcgResult got = kit::filtered_pcg(sparse(a), b, unfiltered, 1e-12, int(size));
    CHECK(got.negative_curvature);
    CHECK_FALSE(got.converged);
    CHECK(got.x.allFinite());
    CHECK(std::isfinite(got.residual));
    CHECK((got.iterations >= 1 && got.iterations <= size));
  }
}
