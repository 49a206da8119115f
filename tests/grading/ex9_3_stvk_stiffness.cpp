// ex 9.3: the element stiffness ∂f/∂x, 9×9 (fem_stvk_stiffness.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "fem_cases.hpp"
#include "fem_stvk_stiffness.hpp"

namespace {
using kit::Matrix9;
using kit::Vec3;
using kit::Vector9;
using kit::test::describe;
using kit::test::random_element;

/// ∂f/∂x by central differences of the forces, the forces themselves by central differences of
/// the energy (fem_cases.hpp): the second derivative of W from its values, good to about 1e-5.
/// Moves of δ = 1e-4 of the element's size balance truncation against the forces' own error.
Matrix9 stiffness_by_differences(const kit::test::RandomElement& e) {
  const double delta = 1e-4 * (e.rest_nodes[1] - e.rest_nodes[0]).norm();
  Matrix9 K;
  for (int node = 0; node < 3; ++node)
    for (int axis = 0; axis < 3; ++axis) {
      auto plus = e, minus = e;
      plus.nodes[node][axis] += delta;
      minus.nodes[node][axis] -= delta;
      plus.F = kit::test::gradient_of(plus.nodes, e.rest.inverse);
      minus.F = kit::test::gradient_of(minus.nodes, e.rest.inverse);
      const kit::ElementForces df =
          kit::test::forces_by_differences(plus) - kit::test::forces_by_differences(minus);
      K.col(3 * node + axis) = df.reshaped() / (2 * delta);
    }
  return K;
}
}  // namespace

TEST_CASE("ex 9.3: the stiffness matches differences of the forces, at rest and deformed",
          "[grade][09-continuum][ex9.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 60; ++trial) {
    const auto e = random_element(rng, trial % 3 == 0 ? 0.0 : 0.4);
    const Matrix9 K = kit::stvk_stiffness(e.F, e.rest.inverse, e.rest.volume, e.lame);
    const Matrix9 expected = stiffness_by_differences(e);
    INFO("trial " << trial << ": " << describe(e) << "\ngot\n" << K << "\nexpected\n" << expected);
    // Leaving out the F dS or the dF S term, or a wrong sign, misses by the stiffness itself.
    CHECK((K - expected).cwiseAbs().maxCoeff() <= 1e-4 * expected.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("ex 9.3: symmetric, blind to translations, and at rest blind to small rotations",
          "[grade][09-continuum][ex9.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const auto e = random_element(rng, 0.4);
    const Matrix9 K = kit::stvk_stiffness(e.F, e.rest.inverse, e.rest.volume, e.lame);
    const double scale = K.cwiseAbs().maxCoeff();
    INFO("trial " << trial << ": " << describe(e) << "\nK =\n" << K);
    CHECK(scale > 0);
    CHECK((K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale);
    for (int axis = 0; axis < 3; ++axis) {
      Vector9 shift = Vector9::Zero();
      for (int node = 0; node < 3; ++node) shift[3 * node + axis] = 1;
      CHECK((K * shift).cwiseAbs().maxCoeff() <= 1e-12 * scale);
    }
  }
  // At an unstressed state (a rigid motion of the rest shape) an infinitesimal rotation ω × x of
  // the nodes stores no energy to second order: K (ω × x) = 0.
  for (int trial = 0; trial < 100; ++trial) {
    const auto e = random_element(rng, 0.0);
    const Matrix9 K = kit::stvk_stiffness(e.F, e.rest.inverse, e.rest.volume, e.lame);
    const double wx = kit::test::uniform(rng, -1, 1), wy = kit::test::uniform(rng, -1, 1);
    const Vec3 omega(wx, wy, kit::test::uniform(rng, -1, 1));
    Vector9 turn;
    for (int node = 0; node < 3; ++node) turn.segment<3>(3 * node) = omega.cross(e.nodes[node] - e.nodes[0]);
    const double size = K.cwiseAbs().maxCoeff() * turn.cwiseAbs().maxCoeff();
    INFO("trial " << trial << ": " << describe(e));
    CHECK((K * turn).cwiseAbs().maxCoeff() <= 1e-12 * size);
  }
}

TEST_CASE("ex 9.3: closed form at rest: the unit right triangle's in-plane stiffness",
          "[grade][09-continuum][ex9.3]") {
  // At F = [I; 0] the stiffness is the linear element's: pulling node 1 along x by dx strains
  // E_xx = dx (Dm = I), so the force on node 1 is −V (λ + 2μ) dx along x and on node 2 −V λ dx along y;
  // out of the plane a flat unstressed membrane has no stiffness at all.
  const kit::Lame lame{3e5, 1e5};
  const double volume = 0.5 * 0.002;
  kit::Matrix32 F = kit::Matrix32::Zero();
  F(0, 0) = F(1, 1) = 1;
  const Matrix9 K = kit::stvk_stiffness(F, kit::Matrix2::Identity(), volume, lame);
  INFO("K =\n" << K);
  CHECK(K(3, 3) == Approx(-volume * (lame.lambda + 2 * lame.mu)).epsilon(1e-14));
  CHECK(K(7, 3) == Approx(-volume * lame.lambda).epsilon(1e-14));
  CHECK(K(4, 3) == Approx(0).margin(1e-14 * lame.mu * volume));
  // Pulling node 1 along y shears the element: E_xy = dy/2, so S_xy = μ dy, and the forces are
  // −V μ dy on node 1 along y and on node 2 along x.
  CHECK(K(4, 4) == Approx(-volume * lame.mu).epsilon(1e-14));
  CHECK(K(6, 4) == Approx(-volume * lame.mu).epsilon(1e-14));
  // Zero to round-off, not bit for bit: accurate differences of one's own forces are a fair answer.
  for (int r = 0; r < 9; ++r) CHECK(K(r, 2) == Approx(0).margin(1e-14 * lame.mu * volume));  // z of node 0
  for (int r = 0; r < 9; ++r) CHECK(K(r, 8) == Approx(0).margin(1e-14 * lame.mu * volume));  // z of node 2
}
