// ex 8.3: the angular velocity from the angular momentum, ω = R I_body⁻¹ Rᵀ L (rigid_angular_velocity.hpp).
#include <cmath>

#include <Eigen/Geometry>
#include <kit_catch.hpp>

#include "cases.hpp"
#include "rigid_angular_velocity.hpp"
#include "rigid_cases.hpp"

namespace {
using kit::Mat3;
using kit::Vec3;
using kit::test::random_matrix;
using kit::test::random_rotation;
using kit::test::random_vector;

/// A body's inertia about its centre of mass and its inverse, both in body axes: principal
/// moments over three decades [kg·m²], about principal axes turned from the body axes.
struct RandomInertia {
  Mat3 inertia, inverse;
};
RandomInertia random_inertia(std::mt19937_64& rng) {
  const Mat3 axes = random_rotation(rng);
  Vec3 moments;
  for (int i = 0; i < 3; ++i) moments[i] = std::pow(10.0, kit::test::uniform(rng, -2, 1));
  return {axes * moments.asDiagonal() * axes.transpose(),
          axes * moments.cwiseInverse().asDiagonal() * axes.transpose()};
}

/// R I⁻¹ Rᵀ L by its sums, ω_i = Σ_jkl R_ij I⁻¹_jk R_lk L_l, and the same sum of absolute values
/// (the size round-off is measured against).
struct Sums {
  Vec3 value, size;
};
Sums literal_formula(const Mat3& r, const Mat3& inverse, const Vec3& l) {
  Sums s{Vec3::Zero(), Vec3::Zero()};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int m = 0; m < 3; ++m) {
          s.value[i] += r(i, j) * inverse(j, k) * r(m, k) * l[m];
          s.size[i] += std::abs(r(i, j) * inverse(j, k) * r(m, k) * l[m]);
        }
  return s;
}
}  // namespace

TEST_CASE(
    "ex 8.3: ω is literally R I⁻¹ Rᵀ L, for rotations and for R that are not (transposed, not inverted)",
    "[grade][08-rigid-bodies][ex8.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    // Half the trials with a rotation, half with any matrix: there Rᵀ ≠ R⁻¹, and the lecture's
    // formula, which the explicit integrator calls with its drifted R, reads Rᵀ.
    const Mat3 r = trial % 2 == 0 ? random_rotation(rng) : random_matrix(rng);
    const RandomInertia body = random_inertia(rng);
    const Vec3 l = random_vector(rng, 10);
    const Sums expected = literal_formula(r, body.inverse, l);
    const Vec3 got = kit::angular_velocity(r, body.inverse, l);
    INFO("trial " << trial << ": L = " << l.transpose() << " kg·m²/s\nR =\n"
                  << r << "\nI_body⁻¹ =\n"
                  << body.inverse << "\ngot      " << got.transpose() << "\nexpected "
                  << expected.value.transpose());
    // Rᵀ I⁻¹ R, I in place of I⁻¹, or R⁻¹ in place of Rᵀ all miss by the size of ω itself.
    for (int i = 0; i < 3; ++i) CHECK(std::abs(got[i] - expected.value[i]) <= 1e-14 * expected.size[i]);
  }
}

TEST_CASE(
    "ex 8.3: for a rotation, ω solves I(t) ω = L with I(t) = R I_body Rᵀ, and ω·L = (RᵀL)ᵀ I⁻¹ (RᵀL) > 0",
    "[grade][08-rigid-bodies][ex8.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 300; ++trial) {
    const Mat3 r = random_rotation(rng);
    const RandomInertia body = random_inertia(rng);
    const Vec3 l = random_vector(rng, 10);
    const Vec3 omega = kit::angular_velocity(r, body.inverse, l);
    INFO("trial " << trial << ": L = " << l.transpose() << ", omega = " << omega.transpose());
    // The world inertia, from I_body itself (not its inverse), applied to ω gives L back.
    const Mat3 world_inertia = r * body.inertia * r.transpose();
    CHECK((world_inertia * omega - l).norm() <= 1e-12 * l.norm());
    // Twice the rotational energy, from the body-frame momentum Rᵀ L.
    const Vec3 lb = r.transpose() * l;
    const double energy = lb.dot(body.inverse * lb);
    CHECK(omega.dot(l) == Approx(energy).epsilon(1e-12));
    CHECK(omega.dot(l) > 0);
  }
}

TEST_CASE("ex 8.3: closed forms: principal axes give L_i / I_i; a quarter turn; a shear; L = 0",
          "[grade][08-rigid-bodies][ex8.3]") {
  const Mat3 inverse = Vec3(1.0, 0.5, 0.25).asDiagonal();  // I_body = diag(1, 2, 4) kg·m²
  // R = I: ω_i = L_i / I_i.
  CHECK((kit::angular_velocity(Mat3::Identity(), inverse, Vec3(2, 4, -8)) - Vec3(2, 2, -2)).norm() <= 1e-15);
  // R = a quarter turn about z, L = x̂ (world): in the body L is −ŷ, so ω_body = −ŷ/2 and back in
  // the world ω = x̂/2. Rᵀ I⁻¹ R gives −x̂/2 and I in place of I⁻¹ gives 2 x̂.
  Mat3 rz;
  rz << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  const Vec3 quarter = kit::angular_velocity(rz, inverse, Vec3(1, 0, 0));
  INFO("quarter turn: omega = " << quarter.transpose());
  CHECK((quarter - Vec3(0.5, 0, 0)).norm() <= 1e-15);
  // A shear R = [[1, 1, 0], [0, 1, 0], [0, 0, 1]] with I⁻¹ = I: R Rᵀ L = (2, 1, 0) for L = x̂,
  // where R R⁻¹ L would give L back.
  Mat3 shear;
  shear << 1, 1, 0, 0, 1, 0, 0, 0, 1;
  const Vec3 sheared = kit::angular_velocity(shear, Mat3::Identity(), Vec3(1, 0, 0));
  INFO("shear: omega = " << sheared.transpose());
  CHECK((sheared - Vec3(2, 1, 0)).norm() <= 1e-15);
  // No momentum, no turn.
  CHECK(kit::angular_velocity(rz, inverse, Vec3::Zero()).norm() == 0);
}
