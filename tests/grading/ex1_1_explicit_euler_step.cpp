// ex 1.1: one explicit Euler step of u' = f(t, u), for any right-hand side (explicit_euler.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "explicit_euler.hpp"

using kit::Vec;
using kit::test::uniform;

TEST_CASE("ex 1.1: explicit Euler on free fall lands on x0 + kΔt·v0 + k(k−1)/2·Δt²·g",
          "[grade][01-free-fall][ex1.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 25; ++trial) {
    const auto c = kit::test::random_fall(rng);
    INFO(kit::test::describe(c));
    const double g = c.g;
    auto f = [g](double, const Vec<2>& u) { return Vec<2>(u[1], g); };
    Vec<2> u(c.x0, c.v0);
    for (long k = 0; k < c.steps; ++k) u = kit::explicit_euler_step(f, double(k) * c.dt, u, c.dt);
    CHECK(u[0] == Approx(kit::test::explicit_euler_x(c)).margin(1e-12 * kit::test::scale(c)));
    CHECK(u[1] == Approx(c.v0 + double(c.steps) * c.dt * g).margin(1e-12 * kit::test::scale(c)));
  }
}

TEST_CASE("ex 1.1: explicit Euler evaluates f once per step, at the start of the step",
          "[grade][01-free-fall][ex1.1]") {
  // u' = cos(t): explicit Euler sums the slopes at the left end of each step.
  long calls = 0;
  std::vector<double> seen_t;
  auto f = [&](double t, const Vec<1>& u) {
    ++calls;
    seen_t.push_back(t);
    return Vec<1>(std::cos(t) + 0 * u[0]);
  };
  const double dt = 0.01;
  Vec<1> u(0.0);
  double left_sum = 0;
  for (int k = 0; k < 300; ++k) {
    u = kit::explicit_euler_step(f, k * dt, u, dt);
    left_sum += dt * std::cos(k * dt);
  }
  CHECK(calls == 300);
  REQUIRE(seen_t.size() == 300);
  CHECK(seen_t[17] == Approx(17 * dt));
  CHECK(u[0] == Approx(left_sum).epsilon(1e-13));
}

TEST_CASE("ex 1.1: explicit Euler is first order: halving Δt halves the error at a fixed time",
          "[grade][01-free-fall][ex1.1]") {
  // u' = λu, u(0) = 1, exact e^{λT}; λ = −2, T = 1.
  auto f = [](double, const Vec<1>& u) { return Vec<1>(-2.0 * u[0]); };
  auto error = [&](long n) {
    const double dt = 1.0 / double(n);
    Vec<1> u(1.0);
    for (long k = 0; k < n; ++k) u = kit::explicit_euler_step(f, double(k) * dt, u, dt);
    return std::abs(u[0] - std::exp(-2.0));
  };
  const double order = std::log2(error(1000) / error(2000));
  CHECK(order == Approx(1.0).margin(0.05));
}

TEST_CASE("ex 1.1: explicit Euler works on a state of any size (here 3 components, float)",
          "[grade][01-free-fall][ex1.1]") {
  auto f = [](float t, const Vec<3, float>& u) { return Vec<3, float>(u[1], -u[0], t); };
  const Vec<3, float> u(1.0f, 2.0f, 3.0f);
  const Vec<3, float> next = kit::explicit_euler_step(f, 0.5f, u, 0.25f);
  CHECK(next[0] == Approx(1.5f));
  CHECK(next[1] == Approx(1.75f));
  CHECK(next[2] == Approx(3.125f));
}
