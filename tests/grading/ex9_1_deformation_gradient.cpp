// ex 9.1: the deformation gradient F = Ds Dm⁻¹ and Green's strain E = ½(FᵀF − I) (fem_strain.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "fem_cases.hpp"
#include "fem_strain.hpp"

namespace {
using kit::Matrix2;
using kit::Matrix32;
using kit::test::describe;
using kit::test::random_element;
}  // namespace

TEST_CASE("ex 9.1: F maps the rest edges onto the current ones, and is the F the nodes were moved by",
          "[grade][09-continuum][ex9.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const auto e = random_element(rng, 0.5);
    const Matrix32 F = kit::deformation_gradient(e.nodes[0], e.nodes[1], e.nodes[2], e.rest.inverse);
    INFO("trial " << trial << ": " << describe(e) << "\ngot F =\n" << F);
    CHECK((F - e.F).norm() <= 1e-12 * e.F.norm());
    // Each rest edge, X1 − X0 and X2 − X0 (the columns of Dm), lands on its current edge; an
    // F built from X2 − X1 or from Dm instead of Dm⁻¹ misses them.
    for (int i = 1; i <= 2; ++i) {
      const kit::Vec3 edge = e.nodes[i] - e.nodes[0];
      CHECK((F * (e.rest_nodes[i] - e.rest_nodes[0]) - edge).norm() <= 1e-12 * edge.norm());
    }
    const kit::Vec3 far_edge = e.nodes[2] - e.nodes[1];
    CHECK((F * (e.rest_nodes[2] - e.rest_nodes[1]) - far_edge).norm() <= 1e-12 * far_edge.norm());
  }
}

TEST_CASE("ex 9.1: a rigid motion in space has no Green strain, to round-off",
          "[grade][09-continuum][ex9.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const auto e = random_element(rng, 0.0);  // F = the first two columns of a rotation
    const Matrix2 E = kit::green_strain(e.F);
    INFO("trial " << trial << ": F =\n" << e.F << "\nE =\n" << E);
    CHECK(E.cwiseAbs().maxCoeff() <= 1e-14);  // E's entries are O(1) sums: a few ulps
  }
  // A quarter turn in the plane, which the small strain reads as a 100% compression (ε = −I).
  Matrix32 quarter;
  quarter << 0, -1, 1, 0, 0, 0;
  CHECK(kit::green_strain(quarter).cwiseAbs().maxCoeff() == 0);
}

TEST_CASE("ex 9.1: closed forms: a stretch by (a, b) has E = diag((a² − 1)/2, (b² − 1)/2); a simple shear",
          "[grade][09-continuum][ex9.1]") {
  for (const double a : {0.5, 1.0, 1.1, 2.0, 3.0})
    for (const double b : {0.25, 1.0, 1.5}) {
      Matrix32 F = Matrix32::Zero();
      F(0, 0) = a;
      F(1, 1) = b;
      const Matrix2 E = kit::green_strain(F);
      INFO("a = " << a << ", b = " << b << ", E =\n" << E);
      CHECK(E(0, 0) == Approx((a * a - 1) / 2).margin(1e-16));
      CHECK(E(1, 1) == Approx((b * b - 1) / 2).margin(1e-16));
      CHECK(E(0, 1) == 0);
      CHECK(E(1, 0) == 0);
    }
  // Simple shear x' = x + γ y: FᵀF = [[1, γ], [γ, 1 + γ²]], so E = [[0, γ/2], [γ/2, γ²/2]]. The
  // small strain misses the γ²/2.
  const double shear = 0.4;
  Matrix32 F = Matrix32::Zero();
  F << 1, shear, 0, 1, 0, 0;
  const Matrix2 E = kit::green_strain(F);
  INFO("E =\n" << E);
  CHECK(E(0, 0) == Approx(0).margin(1e-16));
  CHECK(E(0, 1) == Approx(shear / 2).epsilon(1e-15));
  CHECK(E(1, 0) == Approx(shear / 2).epsilon(1e-15));
  CHECK(E(1, 1) == Approx(shear * shear / 2).epsilon(1e-15));
}

TEST_CASE("ex 9.1: E is the lecture's ½(∇u + ∇uᵀ + ∇uᵀ∇u) with ∇u = F − I, for a plate in its plane",
          "[grade][09-continuum][ex9.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    Matrix2 grad_u;  // any displacement gradient, rotations and stretches up to 100%
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) grad_u(r, c) = kit::test::uniform(rng, -1, 1);
    Matrix32 F = Matrix32::Zero();
    F.topRows<2>() = Matrix2::Identity() + grad_u;
    const Matrix2 lecture = 0.5 * (grad_u + grad_u.transpose() + grad_u.transpose() * grad_u);
    const Matrix2 E = kit::green_strain(F);
    INFO("trial " << trial << ": grad u =\n" << grad_u << "\nE =\n" << E << "\nlecture =\n" << lecture);
    CHECK((E - lecture).cwiseAbs().maxCoeff() <= 1e-15 * (1 + grad_u.squaredNorm()));
    CHECK(std::abs(E(0, 1) - E(1, 0)) <= 1e-15 * (1 + grad_u.squaredNorm()));  // E is symmetric
  }
}
