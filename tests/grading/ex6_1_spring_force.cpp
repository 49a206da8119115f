// ex 6.1: the force of one cloth spring on its end a (cloth_spring_force.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "cloth_spring_force.hpp"

namespace {
using kit::Vec3;
Vec3 random_vector(std::mt19937_64& rng, double scale) {
  return {kit::test::uniform(rng, -scale, scale), kit::test::uniform(rng, -scale, scale),
          kit::test::uniform(rng, -scale, scale)};
}
}  // namespace

TEST_CASE("ex 6.1: F_a = [K (L0 − l) − μ (v_a − v_b)·x̂] x̂ on random springs",
          "[grade][06-cloth-explicit][ex6.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 xa = random_vector(rng, 2), xb = random_vector(rng, 2), va = random_vector(rng, 5),
               vb = random_vector(rng, 5);
    const double rest = kit::test::uniform(rng, 0.01, 3);
    const kit::SpringFamily family{std::pow(10, kit::test::uniform(rng, 0, 5)),
                                   kit::test::uniform(rng, 0, 20)};
    // The closed form, written out by components.
    const double dx = xa[0] - xb[0], dy = xa[1] - xb[1], dz = xa[2] - xb[2];
    const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double rate = ((va[0] - vb[0]) * dx + (va[1] - vb[1]) * dy + (va[2] - vb[2]) * dz) / l;
    const double magnitude = family.stiffness * (rest - l) - family.damping * rate;
    const Vec3 expected(magnitude * dx / l, magnitude * dy / l, magnitude * dz / l);
    const Vec3 got = kit::spring_force(xa, xb, va, vb, rest, family);
    INFO("trial " << trial << ", l = " << l << ", L0 = " << rest);
    CHECK((got - expected).norm() <= 1e-11 * (expected.norm() + family.stiffness * rest));
  }
}

TEST_CASE("ex 6.1: Newton's third law, F(b, a) = −F(a, b)", "[grade][06-cloth-explicit][ex6.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 xa = random_vector(rng, 1), xb = random_vector(rng, 1), va = random_vector(rng, 3),
               vb = random_vector(rng, 3);
    const kit::SpringFamily family{kit::test::uniform(rng, 1, 1e4), kit::test::uniform(rng, 0, 5)};
    const Vec3 fa = kit::spring_force(xa, xb, va, vb, 0.7, family),
               fb = kit::spring_force(xb, xa, vb, va, 0.7, family);
    CHECK((fa + fb).norm() <= 1e-12 * fa.norm() + 1e-300);
    CHECK(fa.norm() > 0);
  }
}

TEST_CASE("ex 6.1: damping resists only a change of length, never a common motion or a turn",
          "[grade][06-cloth-explicit][ex6.1]") {
  const kit::SpringFamily family{100, 3};
  const Vec3 xa(1, 0, 0), xb(0, 0, 0);
  // At rest length: moving together, or turning (velocity across the spring), gives no force.
  CHECK(kit::spring_force(xa, xb, {4, -2, 7}, {4, -2, 7}, 1.0, family).norm() < 1e-12);
  CHECK(kit::spring_force(xa, xb, {0, 5, 0}, {0, -5, 3}, 1.0, family).norm() < 1e-12);
  // Stretching at 2 m/s: damping −μ·2 along x̂ = +x, on top of nothing (l = L0).
  const Vec3 f = kit::spring_force(xa, xb, {2, 0, 0}, {0, 0, 0}, 1.0, family);
  CHECK(f[0] == Approx(-6.0).epsilon(1e-12));
  CHECK(std::abs(f[1]) + std::abs(f[2]) < 1e-12);
}

TEST_CASE("ex 6.1: undamped, the force is minus the gradient of ½K(l − L0)²",
          "[grade][06-cloth-explicit][ex6.1]") {
  auto rng = kit::test::random_engine();
  const Vec3 zero = Vec3::Zero();
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 xa = random_vector(rng, 1), xb = random_vector(rng, 1);
    const double rest = kit::test::uniform(rng, 0.1, 2), k = kit::test::uniform(rng, 1, 1000), h = 1e-6;
    const auto energy = [&](const Vec3& p) {
      const double e = (p - xb).norm() - rest;
      return 0.5 * k * e * e;
    };
    const Vec3 f = kit::spring_force(xa, xb, zero, zero, rest, {k, 0});
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 step = zero;
      step[axis] = h;
      CHECK(f[axis] == Approx(-(energy(xa + step) - energy(xa - step)) / (2 * h)).margin(1e-6 * k));
    }
  }
}

TEST_CASE("ex 6.1: a spring of zero length has no direction and no force",
          "[grade][06-cloth-explicit][ex6.1]") {
  const Vec3 p(0.3, -1, 2);
  const Vec3 f = kit::spring_force(p, p, {1, 0, 0}, {0, 0, 0}, 0.5, {100, 1});
  CHECK(f.allFinite());
  CHECK(f.norm() == 0);
}
