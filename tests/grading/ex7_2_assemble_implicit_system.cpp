// ex 7.2: the linear system A Δv = b of one implicit cloth step (cloth_assembly.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <Eigen/Dense>
#include <kit_catch.hpp>

#include "cases.hpp"
#include "cloth_assembly.hpp"

namespace {
using kit::Mat3;
using kit::Vec3;

/// A small random cloth: n nodes, springs between random distinct nodes (a pair may repeat),
/// random state, forces, masses, and per-spring damping (zero for some springs).
struct RandomCloth {
  kit::Springs springs;
  kit::NodeArray x, v, f;
  Eigen::VectorXd masses;
  std::vector<Mat3> blocks;  // ∂f_a/∂x_a of each spring
  std::optional<double> drag;
  double h = 0;
};

kit::NodeArray random_nodes(std::mt19937_64& rng, long n, double scale) {
  kit::NodeArray a(n, 3);
  for (long i = 0; i < n; ++i)
    for (int axis = 0; axis < 3; ++axis) a(i, axis) = kit::test::uniform(rng, -scale, scale);
  return a;
}

long random_index(std::mt19937_64& rng, long n) { return std::uniform_int_distribution<long>(0, n - 1)(rng); }

/// The physical stiffness block of a spring, written as −K [(L0/l) x̂x̂ᵀ + (1 − L0/l) I], entry by entry.
Mat3 physical_block(const Vec3& xa, const Vec3& xb, double rest, double k) {
  const Vec3 d = xb - xa;
  const double squared = d.dot(d), l = std::sqrt(squared);
  Mat3 j;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      j(r, c) = -k * ((rest / l) * d[r] * d[c] / squared + (r == c ? 1 - rest / l : 0.0));
  return j;
}

/// A random symmetric 3×3 matrix, entries up to `scale`: a block the assembly must use as given.
Mat3 random_symmetric(std::mt19937_64& rng, double scale) {
  Mat3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = r; c < 3; ++c) m(r, c) = m(c, r) = kit::test::uniform(rng, -scale, scale);
  return m;
}

RandomCloth random_cloth(std::mt19937_64& rng, bool physical_blocks) {
  RandomCloth cloth;
  const long n = 2 + random_index(rng, 7);
  cloth.x = random_nodes(rng, n, 1);
  cloth.v = random_nodes(rng, n, 2);
  cloth.f = random_nodes(rng, n, 5);
  cloth.masses = Eigen::VectorXd::NullaryExpr(n, [&] { return kit::test::uniform(rng, 0.01, 2); });
  const long count = 1 + random_index(rng, 14);
  for (long s = 0; s < count; ++s) {
    const long a = random_index(rng, n);
    long b = random_index(rng, n - 1);
    if (b >= a) ++b;  // distinct ends
    const double k = std::pow(10.0, kit::test::uniform(rng, 0, 4));
    const double mu = kit::test::uniform(rng, 0, 1) < 0.25 ? 0.0 : kit::test::uniform(rng, 0, 5);
    const double rest = kit::test::uniform(rng, 0.1, 2);
    cloth.springs.add(a, b, rest, {k, mu}, kit::SpringKind::structural);
    cloth.blocks.push_back(physical_blocks ? physical_block(cloth.x.row(a), cloth.x.row(b), rest, k)
                                           : random_symmetric(rng, k));
  }
  if (kit::test::uniform(rng, 0, 1) < 0.5) cloth.drag = kit::test::uniform(rng, 0, 3);
  cloth.h = kit::test::uniform(rng, 1e-4, 0.05);
  return cloth;
}

/// The reference, dense: the global ∂f/∂x and ∂f/∂v (3n×3n) are built first, then
/// A = M − h ∂f/∂v − h² ∂f/∂x and b = h (f + h ∂f/∂x v) as matrix expressions.
struct DenseSystem {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
};
DenseSystem dense_reference(const RandomCloth& cloth) {
  const Eigen::Index n = cloth.x.rows(), size = 3 * n;
  Eigen::MatrixXd dfdx = Eigen::MatrixXd::Zero(size, size), dfdv = Eigen::MatrixXd::Zero(size, size);
  Eigen::VectorXd mass_diagonal(size), force(size), velocity(size);
  for (Eigen::Index i = 0; i < n; ++i)
    for (int axis = 0; axis < 3; ++axis) {
      mass_diagonal[3 * i + axis] = cloth.masses[i];
      force[3 * i + axis] = cloth.f(i, axis);
      velocity[3 * i + axis] = cloth.v(i, axis);
    }
  for (std::size_t s = 0; s < cloth.springs.size(); ++s) {
    const Eigen::Index a = cloth.springs.a[s], b = cloth.springs.b[s];
    const Vec3 d = cloth.x.row(b) - cloth.x.row(a);
    const double squared = d.squaredNorm();
    Mat3 damping = Mat3::Zero();  // −μ x̂x̂ᵀ; none for coincident ends
    if (squared > 0) damping = -(cloth.springs.damping[s] / squared) * (d * d.transpose());
    // Signs of the four blocks: + on (a, a) and (b, b), − on (a, b) and (b, a).
    const std::array<std::tuple<Eigen::Index, Eigen::Index, double>, 4> placed{
        {{a, a, 1.0}, {b, b, 1.0}, {a, b, -1.0}, {b, a, -1.0}}};
    for (const auto& [row, col, sign] : placed) {
      dfdx.block<3, 3>(3 * row, 3 * col) += sign * cloth.blocks[s];
      dfdv.block<3, 3>(3 * row, 3 * col) += sign * damping;
    }
  }
  if (cloth.drag) dfdv.diagonal() -= *cloth.drag * mass_diagonal;  // f_drag = −m c v
  DenseSystem out;
  out.A = Eigen::MatrixXd(mass_diagonal.asDiagonal()) - cloth.h * dfdv - cloth.h * cloth.h * dfdx;
  out.b = cloth.h * force + cloth.h * cloth.h * (dfdx * velocity);
  return out;
}

struct Assembled {
  Eigen::MatrixXd A;
  Eigen::VectorXd b;
};
Assembled assemble(const RandomCloth& cloth) {
  const kit::ImplicitSystemInput in{cloth.springs, cloth.x,      cloth.v,    cloth.f,
                                    cloth.masses,  cloth.blocks, cloth.drag, cloth.h};
  kit::SparseMatrix A;
  Eigen::VectorXd b;
  kit::assemble_implicit_system(in, A, b);
  return {Eigen::MatrixXd(A), b};
}

double largest(const Eigen::MatrixXd& m) { return m.size() ? m.cwiseAbs().maxCoeff() : 0.0; }
}  // namespace

TEST_CASE("ex 7.2: A = M − h ∂f/∂v − h² ∂f/∂x and b = h (f + h ∂f/∂x v) on random small cloths",
          "[grade][07-cloth-implicit][ex7.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 200; ++trial) {
    const RandomCloth cloth = random_cloth(rng, trial % 2 == 0);
    const Eigen::Index size = 3 * cloth.x.rows();
    const DenseSystem expected = dense_reference(cloth);
    const Assembled got = assemble(cloth);
    INFO("trial " << trial << ": " << cloth.x.rows() << " nodes, " << cloth.springs.size()
                  << " springs, h = " << cloth.h << " s, drag "
                  << (cloth.drag ? std::to_string(*cloth.drag) : std::string("none"))
                  << (trial % 2 == 0 ? ", physical blocks" : ", arbitrary symmetric blocks"));
    REQUIRE((got.A.rows() == size && got.A.cols() == size));
    REQUIRE(got.b.size() == size);
    INFO("A got\n" << got.A << "\nA expected\n" << expected.A);
    CHECK(largest(got.A - expected.A) <= 1e-12 * largest(expected.A));
    INFO("b got " << got.b.transpose() << "\nb expected " << expected.b.transpose());
    CHECK(largest(got.b - expected.b) <=
          1e-12 * (largest(expected.b) + cloth.h * cloth.h * largest(expected.A)));
  }
}

TEST_CASE("ex 7.2: A is symmetric, and a common velocity change meets only the mass and the drag",
          "[grade][07-cloth-implicit][ex7.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 100; ++trial) {
    const RandomCloth cloth = random_cloth(rng, true);
    const Eigen::Index n = cloth.x.rows();
    const Assembled got = assemble(cloth);
    REQUIRE(got.A.rows() == 3 * n);
    INFO("trial " << trial);
    CHECK(largest(got.A - got.A.transpose()) <= 1e-12 * largest(got.A));
    // A (t, t, …, t): every spring block meets its negative in the same row, so node i gets
    // m_i (1 + h c) t.
    const Vec3 t(kit::test::uniform(rng, -1, 1), kit::test::uniform(rng, -1, 1),
                 kit::test::uniform(rng, -1, 1));
    const Eigen::VectorXd product = got.A * t.replicate(n, 1);
    double worst = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const Vec3 expected = cloth.masses[i] * (1 + cloth.h * cloth.drag.value_or(0)) * t;
      worst = std::max(worst, (product.segment<3>(3 * i) - expected).norm());
    }
    CHECK(worst <= 1e-12 * largest(got.A));
  }
}

TEST_CASE("ex 7.2: at rest, or moving all together, b is h f: the springs' stiffness adds nothing",
          "[grade][07-cloth-implicit][ex7.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 100; ++trial) {
    RandomCloth cloth = random_cloth(rng, trial % 2 == 0);
    const Eigen::Index n = cloth.x.rows();
    Eigen::VectorXd hf(3 * n);
    for (Eigen::Index i = 0; i < n; ++i) hf.segment<3>(3 * i) = cloth.h * cloth.f.row(i).transpose();
    cloth.v.setZero();
    const Assembled at_rest = assemble(cloth);
    REQUIRE(at_rest.b.size() == 3 * n);
    CHECK(largest(at_rest.b - hf) <= 1e-14 * largest(hf));
    const Eigen::RowVector3d common(kit::test::uniform(rng, -3, 3), kit::test::uniform(rng, -3, 3),
                                    kit::test::uniform(rng, -3, 3));
    cloth.v = common.replicate(n, 1);
    const Assembled moving = assemble(cloth);
    REQUIRE(moving.b.size() == 3 * n);
    INFO("trial " << trial << ": b " << moving.b.transpose() << "\nh f " << hf.transpose());
    CHECK(largest(moving.b - hf) <= 1e-12 * (largest(hf) + cloth.h * cloth.h * 3 * largest(at_rest.A)));
  }
}

TEST_CASE("ex 7.2: drag adds exactly h m c on each diagonal entry; no drag is drag 0",
          "[grade][07-cloth-implicit][ex7.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 50; ++trial) {
    RandomCloth cloth = random_cloth(rng, true);
    const Eigen::Index n = cloth.x.rows();
    cloth.drag = std::nullopt;
    const Assembled without = assemble(cloth);
    cloth.drag = 0.0;
    const Assembled zero = assemble(cloth);
    const double c = kit::test::uniform(rng, 0.1, 5);
    cloth.drag = c;
    const Assembled with = assemble(cloth);
    REQUIRE((without.A.rows() == 3 * n && zero.A.rows() == 3 * n && with.A.rows() == 3 * n));
    CHECK(largest(zero.A - without.A) == 0);
    Eigen::VectorXd added(3 * n);
    for (Eigen::Index i = 0; i < n; ++i) added.segment<3>(3 * i).setConstant(cloth.h * c * cloth.masses[i]);
    INFO("trial " << trial << ", c = " << c << " 1/s, h = " << cloth.h << " s");
    CHECK(largest(with.A - without.A - Eigen::MatrixXd(added.asDiagonal())) <= 1e-12 * largest(with.A));
    CHECK(largest(with.b - without.b) == 0);  // the drag force is in f already
  }
}

TEST_CASE("ex 7.2: one damped spring along x at its rest length, by hand",
          "[grade][07-cloth-implicit][ex7.2]") {
  // Nodes 0 at (1, 0, 0) and 1 at the origin, m = 2 kg and 0.5 kg; K = 400 N/m, μ = 3 N·s/m,
  // L0 = 1 m, h = 0.1 s, no drag. At rest length the stiffness block is −K on xx only, so the
  // spring's block of A is B = (h μ + h² K) on xx: 0.3 + 4 = 4.3 kg.
  kit::Springs springs;
  springs.add(0, 1, 1.0, {400, 3}, kit::SpringKind::structural);
  kit::NodeArray x(2, 3), v(2, 3), f(2, 3);
  x << 1, 0, 0, 0, 0, 0;
  v << 1, 2, 3, 0, -1, 0;
  f << 0.5, -1, 2, 0, 0, 1;
  Eigen::VectorXd masses(2);
  masses << 2, 0.5;
  Mat3 block = Mat3::Zero();
  block(0, 0) = -400;
  const std::vector<Mat3> blocks{block};
  const kit::ImplicitSystemInput in{springs, x, v, f, masses, blocks, std::nullopt, 0.1};
  kit::SparseMatrix A;
  Eigen::VectorXd b;
  kit::assemble_implicit_system(in, A, b);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(6, 6);
  expected.diagonal() << 2, 2, 2, 0.5, 0.5, 0.5;
  expected(0, 0) += 4.3, expected(3, 3) += 4.3, expected(0, 3) = -4.3, expected(3, 0) = -4.3;
  REQUIRE((A.rows() == 6 && A.cols() == 6 && b.size() == 6));
  CHECK(largest(Eigen::MatrixXd(A) - expected) <= 1e-12);
  // b = h f + h² J (v_0 − v_1) at node 0, minus that at node 1: J (v_0 − v_1) = (−400, 0, 0).
  Eigen::VectorXd expected_b(6);
  expected_b << 0.05 - 4, -0.1, 0.2, 0 + 4, 0, 0.1;
  CHECK(largest(b - expected_b) <= 1e-12);
}

TEST_CASE("ex 7.2: a spring whose ends meet has no direction: its stiffness block only, no NaN",
          "[grade][07-cloth-implicit][ex7.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 20; ++trial) {
    RandomCloth cloth = random_cloth(rng, false);
    cloth.x.row(cloth.springs.b[0]) = cloth.x.row(cloth.springs.a[0]);  // spring 0 has zero length
    cloth.springs.damping[0] = 2.5;
    const Eigen::Index size = 3 * cloth.x.rows();
    const DenseSystem expected = dense_reference(cloth);
    const Assembled got = assemble(cloth);
    REQUIRE((got.A.rows() == size && got.b.size() == size));
    INFO("trial " << trial);
    CHECK(got.A.allFinite());
    CHECK(got.b.allFinite());
    CHECK(largest(got.A - expected.A) <= 1e-12 * largest(expected.A));
  }
}
