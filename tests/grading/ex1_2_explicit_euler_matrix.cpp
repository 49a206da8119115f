// ex 1.2: explicit Euler in matrix form, u_{k+1} = (I + Δt A) u_k + Δt b (explicit_euler.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "explicit_euler.hpp"

using kit::test::uniform;

TEST_CASE("ex 1.2: matrix-form explicit Euler on free fall gives k(k−1)/2·Δt²·g",
          "[grade][01-free-fall][ex1.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 25; ++trial) {
    const auto c = kit::test::random_fall(rng);
    INFO(kit::test::describe(c));
    const kit::ExplicitEulerAffine<2> euler(kit::test::affine(c), c.dt);
    kit::Vec2 u(c.x0, c.v0);
    for (long k = 0; k < c.steps; ++k) u = euler.step(u);
    CHECK(u[0] == Approx(kit::test::explicit_euler_x(c)).margin(1e-12 * kit::test::scale(c)));
    CHECK(u[1] == Approx(c.v0 + double(c.steps) * c.dt * c.g).margin(1e-12 * kit::test::scale(c)));
  }
}

TEST_CASE("ex 1.2: one step equals (I + Δt A) u + Δt b for random 3×3 systems",
          "[grade][01-free-fall][ex1.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 20; ++trial) {
    const auto s = kit::test::random_system<3>(rng);
    const auto u = kit::test::random_state<3>(rng);
    const double dt = uniform(rng, 1e-4, 0.5);
    const kit::Vec<3> expected = u + dt * (s.A * u + s.b);  // u + Δt·f(u)
    const kit::Vec<3> got = kit::ExplicitEulerAffine<3>(s, dt).step(u);
    CHECK((got - expected).norm() <= 1e-12 * (1 + expected.norm()));
  }
}

TEST_CASE("ex 1.2: explicit Euler amplifies an undamped oscillation by sqrt(1 + ω²Δt²) per step",
          "[grade][01-free-fall][ex1.2]") {
  // A = [[0, 1], [−ω², 0]], b = 0: eigenvalues of I + ΔtA are 1 ± iωΔt (ERRATA item 4).
  const double omega = 3.0, dt = 0.05;
  kit::AffineSystem<2> spring;
  spring.A << 0, 1, -omega * omega, 0;
  spring.b << 0, 0;
  const kit::ExplicitEulerAffine<2> euler(spring, dt);
  kit::Vec2 u(1.0, 0.0);
  auto energy = [&](const kit::Vec2& s) { return omega * omega * s[0] * s[0] + s[1] * s[1]; };
  for (int k = 0; k < 100; ++k) {
    const double before = energy(u);
    u = euler.step(u);
    CHECK(std::sqrt(energy(u) / before) == Approx(std::sqrt(1 + omega * omega * dt * dt)).epsilon(1e-12));
  }
}
