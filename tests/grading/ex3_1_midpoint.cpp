// ex 3.1: the midpoint Runge–Kutta step, as the lecture writes it (midpoint.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "midpoint.hpp"

using kit::Vec;

TEST_CASE("ex 3.1: midpoint RK2 reproduces free fall exactly: 1e-12 relative after 1e4 steps",
          "[grade][03-rk2][ex3.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 10; ++trial) {
    auto c = kit::test::random_fall(rng);
    c.steps = 10'000;
    INFO(kit::test::describe(c));
    const double g = c.g;
    auto f = [g](double, const Vec<2>& u) { return Vec<2>(u[1], g); };
    Vec<2> u(c.x0, c.v0);
    for (long k = 0; k < c.steps; ++k) u = kit::midpoint_step(f, double(k) * c.dt, u, c.dt);
    const double t = double(c.steps) * c.dt;
    CHECK(u[0] ==
          Approx(c.x0 + c.v0 * t + 0.5 * g * t * t).epsilon(1e-12).margin(1e-12 * kit::test::scale(c)));
  }
}

TEST_CASE("ex 3.1: two evaluations per step, the second at t + Δt/2 from the half step",
          "[grade][03-rk2][ex3.1]") {
  long calls = 0;
  auto f = [&](double t, const Vec<1>&) {
    ++calls;
    return Vec<1>(std::cos(t));
  };
  const double dt = 0.01;
  Vec<1> u(0.0);
  double midpoint_sum = 0;
  for (int k = 0; k < 300; ++k) {
    u = kit::midpoint_step(f, k * dt, u, dt);
    midpoint_sum += dt * std::cos(k * dt + dt / 2);
  }
  CHECK(calls == 600);
  CHECK(u[0] == Approx(midpoint_sum).epsilon(1e-13));
}

TEST_CASE("ex 3.1: midpoint RK2 is second order on the spring", "[grade][03-rk2][ex3.1]") {
  const auto error = [](long n) {
    return kit::test::damped_spring_error([](const auto& f, double t, const kit::Vec2& u,
                                             double dt) { return kit::midpoint_step(f, t, u, dt); },
                                          n);
  };
  CHECK(kit::test::observed_order(error, 1000) == Approx(2.0).margin(0.05));
}
