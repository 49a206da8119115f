// ex 2.3: symplectic Euler, v first, then x with the new v (symplectic_euler.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "symplectic_euler.hpp"

namespace {
// ω = 1 rad/s oscillator x'' = −x.
const auto oscillator = [](double, const kit::Vec<1>& x, const kit::Vec<1>&) { return kit::Vec<1>(-x[0]); };
}  // namespace

TEST_CASE("ex 2.3: one step is v' = v + Δt a(x, v), then x' = x + Δt v' (the new velocity)",
          "[grade][02-spring-stability][ex2.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 50; ++trial) {
    const auto spring = kit::test::random_spring(rng);
    const double dt = kit::test::uniform(rng, 1e-4, 0.1), x = kit::test::uniform(rng, -3, 3),
                 v = kit::test::uniform(rng, -3, 3);
    INFO(kit::test::describe(spring) << ", dt = " << dt);
    auto accel = [&](double, const kit::Vec<1>& p, const kit::Vec<1>& q) {
      return kit::Vec<1>((spring.stiffness * (spring.rest_length - p[0]) - spring.damping * q[0]) /
                         spring.mass);
    };
    const kit::Vec2 next = kit::symplectic_euler_step(accel, 0.0, kit::Vec2(x, v), dt);
    const double v_new =
        v + dt * (spring.stiffness * (spring.rest_length - x) - spring.damping * v) / spring.mass;
    CHECK(next[1] == Approx(v_new).epsilon(1e-12).margin(1e-12));
    CHECK(next[0] == Approx(x + dt * v_new).epsilon(1e-12).margin(1e-12));
  }
}

TEST_CASE("ex 2.3: below ω·Δt = 2 the energy stays within (2 + ωΔt)/(2 − ωΔt) of its start for 1e6 steps",
          "[grade][02-spring-stability][ex2.3]") {
  // The step preserves Q = x² + v² − Δt·x·v exactly (ω = 1), which pins E = (x² + v²)/2 between
  // (1 − ωΔt/2) and (1 + ωΔt/2) times Q.
  for (double h : {0.1, 1.0, 1.9}) {
    INFO("omega*dt = " << h);
    // The million steps run in the student's program, which returns every state for the check.
    double worst = 1.0;
    for (const kit::Vec2& u :
         kit::remote::symplectic_euler_oscillator_orbit(kit::Vec2(1.0, 0.0), h, 1'000'000))
      worst = std::max(worst, u.squaredNorm());
    CHECK(worst <= (2 + h) / (2 - h) * (1 + 1e-9));
    CHECK(worst >= 1.0);
  }
}

TEST_CASE("ex 2.3: above ω·Δt = 2 the energy blows up", "[grade][02-spring-stability][ex2.3]") {
  kit::Vec2 u(1.0, 0.0);
  for (int k = 0; k < 200; ++k) u = kit::symplectic_euler_step(oscillator, 0.0, u, 2.05);
  CHECK(u.squaredNorm() > 1e10);
}

TEST_CASE("ex 2.3: it works for several positions at once (a 2-D particle)",
          "[grade][02-spring-stability][ex2.3]") {
  auto accel = [](double, const kit::Vec<2>& x, const kit::Vec<2>&) { return kit::Vec<2>(-x[0], -4 * x[1]); };
  const kit::Vec<4> u(1.0, 2.0, 0.5, -1.0);  // (x1, x2, v1, v2)
  const kit::Vec<4> next = kit::symplectic_euler_step(accel, 0.0, u, 0.1);
  CHECK(next[2] == Approx(0.5 - 0.1));
  CHECK(next[3] == Approx(-1.0 - 0.8));
  CHECK(next[0] == Approx(1.0 + 0.1 * 0.4));
  CHECK(next[1] == Approx(2.0 + 0.1 * -1.8));
}
