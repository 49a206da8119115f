// ex 3.2 (bonus): the classical fourth-order Runge–Kutta step (rk4.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "rk4.hpp"

using kit::Vec;

TEST_CASE("ex 3.2: RK4 integrates u' = t³ exactly (Simpson's rule) with four evaluations per step",
          "[grade][03-rk2][ex3.2]") {
  long calls = 0;
  auto f = [&](double t, const Vec<1>&) {
    ++calls;
    return Vec<1>(t * t * t);
  };
  Vec<1> u(0.0);
  for (int k = 0; k < 10; ++k) u = kit::rk4_step(f, 0.1 * k, u, 0.1);
  CHECK(u[0] == Approx(0.25).epsilon(1e-14));
  CHECK(calls == 40);
}

TEST_CASE("ex 3.2: RK4 is fourth order on the spring", "[grade][03-rk2][ex3.2]") {
  const auto error = [](long n) {
    return kit::test::damped_spring_error(
        [](const auto& f, double t, const kit::Vec2& u, double dt) { return kit::rk4_step(f, t, u, dt); }, n);
  };
  CHECK(kit::test::observed_order(error, 200) == Approx(4.0).margin(0.1));
}
