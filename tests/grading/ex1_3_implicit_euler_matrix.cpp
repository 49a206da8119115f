// ex 1.3: implicit Euler in matrix form, (I − Δt A) u_{k+1} = u_k + Δt b (implicit_euler.hpp).
#include <cmath>

#include <catch2/catch.hpp>

#include "implicit_euler.hpp"
#include "random_cases.hpp"

using kit::test::uniform;

TEST_CASE("ex 1.3: matrix-form implicit Euler on free fall gives k(k+1)/2·Δt²·g",
          "[grade][01-free-fall][ex1.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 25; ++trial) {
    const auto c = kit::test::random_fall(rng);
    INFO("x0 = " << c.x0 << " m, v0 = " << c.v0 << " m/s, g = " << c.g << " m/s², dt = " << c.dt << " s, k = " << c.steps);
    kit::AffineSystem<2> fall;
    fall.A << 0, 1, 0, 0;
    fall.b << 0, c.g;
    const kit::ImplicitEulerAffine<2> euler(fall, c.dt);
    kit::Vec2 u(c.x0, c.v0);
    for (long k = 0; k < c.steps; ++k) u = euler.step(u);
    const double k = double(c.steps);
    const double x = c.x0 + k * c.dt * c.v0 + 0.5 * k * (k + 1) * c.dt * c.dt * c.g;
    const double scale = std::abs(c.x0) + std::abs(c.v0) * k * c.dt + std::abs(c.g) * k * k * c.dt * c.dt + 1;
    CHECK(u[0] == Approx(x).margin(1e-12 * scale));
    CHECK(u[1] == Approx(c.v0 + k * c.dt * c.g).margin(1e-12 * scale));
  }
}

TEST_CASE("ex 1.3: each step solves (I − Δt A) u_{k+1} = u_k + Δt b for random 3×3 systems",
          "[grade][01-free-fall][ex1.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 20; ++trial) {
    kit::AffineSystem<3> s;
    for (int i = 0; i < 9; ++i) s.A(i / 3, i % 3) = uniform(rng, -5, 5);
    for (int i = 0; i < 3; ++i) s.b[i] = uniform(rng, -5, 5);
    const kit::Vec<3> u(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
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
