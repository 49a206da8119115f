// ex 9.2: St Venant–Kirchhoff's stress S = λ tr(E) I + 2μ E and the element's forces −V F S Dm⁻ᵀ
// (fem_stvk_forces.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "fem_cases.hpp"
#include "fem_stvk_forces.hpp"

namespace {
using kit::ElementForces;
using kit::Matrix2;
using kit::Matrix32;
using kit::Vec3;
using kit::test::describe;
using kit::test::random_element;
}  // namespace

TEST_CASE("ex 9.2: S is λ tr(E) I + 2μ E, entry by entry", "[grade][09-continuum][ex9.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    Matrix2 E;
    E(0, 0) = kit::test::uniform(rng, -0.5, 0.5);
    E(1, 1) = kit::test::uniform(rng, -0.5, 0.5);
    E(0, 1) = E(1, 0) = kit::test::uniform(rng, -0.5, 0.5);
    const kit::Lame lame{std::pow(10.0, kit::test::uniform(rng, 3, 8)),
                         std::pow(10.0, kit::test::uniform(rng, 3, 8))};
    const Matrix2 S = kit::stvk_stress(E, lame);
    const double trace = E(0, 0) + E(1, 1);
    INFO("trial " << trial << ": E =\n"
                  << E << "\nlambda = " << lame.lambda << ", mu = " << lame.mu << "\nS =\n"
                  << S);
    const double size = (std::abs(lame.lambda) + 2 * lame.mu) * E.cwiseAbs().maxCoeff();
    CHECK(std::abs(S(0, 0) - (lame.lambda * trace + 2 * lame.mu * E(0, 0))) <= 1e-14 * size);
    CHECK(std::abs(S(1, 1) - (lame.lambda * trace + 2 * lame.mu * E(1, 1))) <= 1e-14 * size);
    // Off the diagonal only μ acts: λ there, or μ in place of 2μ, misses.
    CHECK(std::abs(S(0, 1) - 2 * lame.mu * E(0, 1)) <= 1e-14 * size);
    CHECK(std::abs(S(1, 0) - 2 * lame.mu * E(1, 0)) <= 1e-14 * size);
  }
}

TEST_CASE("ex 9.2: the forces are minus the energy's gradient (central differences), on every node and axis",
          "[grade][09-continuum][ex9.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const auto e = random_element(rng, 0.4);
    const ElementForces f = kit::stvk_forces(e.F, e.rest.inverse, e.rest.volume, e.lame);
    const ElementForces expected = kit::test::forces_by_differences(e);
    INFO("trial " << trial << ": " << describe(e) << "\ngot\n" << f << "\nexpected\n" << expected);
    // The differences are good to about 1e-8 of the largest force; a wrong sign, a missing F,
    // Dm⁻¹ in place of Dm⁻ᵀ or the area forgotten miss by the force itself.
    CHECK((f - expected).cwiseAbs().maxCoeff() <= 1e-6 * expected.cwiseAbs().maxCoeff());
  }
}

TEST_CASE("ex 9.2: no net force and no net moment; none at rest or under a rigid motion",
          "[grade][09-continuum][ex9.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const auto e = random_element(rng, 0.4);
    const ElementForces f = kit::stvk_forces(e.F, e.rest.inverse, e.rest.volume, e.lame);
    const double scale = f.cwiseAbs().maxCoeff();
    INFO("trial " << trial << ": " << describe(e) << "\nforces\n" << f);
    CHECK(scale > 0);
    CHECK(f.rowwise().sum().norm() <= 1e-13 * scale);
    // Σ x_i × f_i = 0: the energy does not change when the element turns, so its forces cannot turn it.
    Vec3 moment = Vec3::Zero();
    for (int i = 0; i < 3; ++i) moment += (e.nodes[i] - e.nodes[0]).cross(Vec3(f.col(i)));
    const double arm = (e.nodes[1] - e.nodes[0]).norm() + (e.nodes[2] - e.nodes[0]).norm();
    CHECK(moment.norm() <= 1e-13 * scale * arm);
    // A rigid motion of the same element: no force at all.
    const auto rigid = random_element(rng, 0.0);
    const ElementForces none = kit::stvk_forces(rigid.F, rigid.rest.inverse, rigid.rest.volume, rigid.lame);
    const double typical = rigid.rest.volume * rigid.lame.mu * rigid.rest.inverse.norm();
    CHECK(none.cwiseAbs().maxCoeff() <= 1e-14 * typical);
  }
}

TEST_CASE("ex 9.2: closed form: a unit square's lower triangle stretched along x",
          "[grade][09-continuum][ex9.2]") {
  // Rest (0,0) (1,0) (0,1), thickness 0.01 m, so V = 0.005 m³ and Dm = I. Stretch x by a:
  // E = diag((a² − 1)/2, 0), S = diag((λ + 2μ) E_xx, λ E_xx), P = F S = diag(a S_xx, S_yy, 0)
  // and H = −V P: node 1 pulled back by V a S_xx along x, node 2 by V S_yy along y.
  const kit::Lame lame{2e5, 1e5};  // Pa
  const double a = 1.2, volume = 0.005;
  Matrix32 F = Matrix32::Zero();
  F(0, 0) = a;
  F(1, 1) = 1;
  const double exx = (a * a - 1) / 2;
  const ElementForces f = kit::stvk_forces(F, Matrix2::Identity(), volume, lame);
  ElementForces expected = ElementForces::Zero();
  expected(0, 1) = -volume * a * (lame.lambda + 2 * lame.mu) * exx;
  expected(1, 2) = -volume * lame.lambda * exx;
  expected.col(0) = -(expected.col(1) + expected.col(2));
  INFO("got\n" << f << "\nexpected\n" << expected);
  CHECK((f - expected).cwiseAbs().maxCoeff() <= 1e-12 * expected.cwiseAbs().maxCoeff());
}
