// ex 2.1: the spring as u' = A u + b (spring_system.hpp).
#include <kit_catch.hpp>

#include <kit/ode/reference_solver.hpp>

#include "cases.hpp"
#include "spring_system.hpp"

TEST_CASE("ex 2.1: A u + b is (v, (K (L0 − x) − μ v)/m) for random springs and states",
          "[grade][02-spring-stability][ex2.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 50; ++trial) {
    const auto spring = kit::test::random_spring(rng);
    INFO(kit::test::describe(spring));
    const auto s = kit::spring_system(spring);
    const kit::Vec2 u(kit::test::uniform(rng, -5, 5), kit::test::uniform(rng, -5, 5));
    const kit::Vec2 f = s.A * u + s.b;
    const double force = spring.stiffness * (spring.rest_length - u[0]) - spring.damping * u[1];
    CHECK(f[0] == Approx(u[1]).margin(1e-12));
    CHECK(f[1] == Approx(force / spring.mass).epsilon(1e-12).margin(1e-9));
  }
}

TEST_CASE("ex 2.1: the rest length at zero velocity is an equilibrium: A (L0, 0) + b = 0",
          "[grade][02-spring-stability][ex2.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 20; ++trial) {
    const auto spring = kit::test::random_spring(rng);
    const auto s = kit::spring_system(spring);
    CHECK((s.A * kit::Vec2(spring.rest_length, 0.0) + s.b).norm() <=
          1e-12 * (1 + spring.stiffness / spring.mass));
  }
}

TEST_CASE("ex 2.1: integrating u' = A u + b follows the closed-form motion in every damping regime",
          "[grade][02-spring-stability][ex2.1]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 10; ++trial) {
    const auto spring = kit::test::random_spring(rng);
    INFO(kit::test::describe(spring));
    const kit::Vec2 u0(spring.rest_length + 0.3, -0.5);
    const double t = 3.0 / spring.omega();
    const auto gsl = kit::reference_solution(kit::spring_system(spring), 0.0, u0, {t});
    const kit::Vec2 exact = kit::spring_motion(spring, u0, t);
    CHECK(gsl.u[0][0] == Approx(exact[0]).margin(1e-8));
    CHECK(gsl.u[0][1] == Approx(exact[1]).margin(1e-8 * spring.omega()));
  }
}
