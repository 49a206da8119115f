// ex 1.3: implicit Euler in matrix form, (I − Δt A) u_{k+1} = u_k + Δt b (implicit_euler.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "implicit_euler.hpp"

using kit::test::uniform;

TEST_CASE("ex 1.3: matrix-form implicit Euler on free fall gives k(k+1)/2·Δt²·g",
          "[grade][01-free-fall][ex1.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 25; ++trial) {
    const auto c = kit::test::random_fall(rng);
    INFO(kit::test::describe(c));
    const kit::ImplicitEulerAffine<2> euler(kit::test::affine(c), c.dt);
    kit::Vec2 u(c.x0, c.v0);
    for (long k = 0; k < c.steps; ++k) u = euler.step(u);
    CHECK(u[0] == Approx(kit::test::implicit_euler_x(c)).margin(1e-12 * kit::test::scale(c)));
    CHECK(u[1] == Approx(c.v0 + double(c.steps) * c.dt * c.g).margin(1e-12 * kit::test::scale(c)));
  }
}

TEST_CASE("ex 1.3: each step solves (I − Δt A) u_{k+1} = u_k + Δt b for random 3×3 systems",
          "[grade][01-free-fall][ex1.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 20; ++trial) {
    const auto s = kit::test::random_system<3>(rng);
    const auto u = kit::test::random_state<3>(rng);
    const double dt = uniform(rng, 1e-4, 0.05);  // keeps I − ΔtA well conditioned
    const kit::Vec<3> next = kit::ImplicitEulerAffine<3>(s, dt).step(u);
    const kit::Vec<3> residual = (kit::Mat<3>::Identity() - dt * s.A) * next - (u + dt * s.b);
    CHECK(residual.norm() <= 1e-12 * (1 + u.norm() + next.norm()));
  }
}

TEST_CASE("ex 1.3: implicit Euler stays stable where explicit Euler explodes (u' = −1000 u, Δt = 0.1)",
          "[grade][01-free-fall][ex1.3]") {
  // Amplification 1/(1 + 1000·0.1) = 1/101 per step; explicit Euler's would be |1 − 100| = 99.
  kit::AffineSystem<1> decay;
  decay.A << -1000.0;
  decay.b << 0.0;
  const kit::ImplicitEulerAffine<1> euler(decay, 0.1);
  kit::Vec<1> u(1.0);
  for (int k = 0; k < 10; ++k) {
    const double before = u[0];
    u = euler.step(u);
    CHECK(u[0] == Approx(before / 101.0).epsilon(1e-13));
  }
}
