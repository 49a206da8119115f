// ex 2.2: implicit Euler on the damped spring, solved by hand (implicit_euler_spring.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "implicit_euler_spring.hpp"

TEST_CASE("ex 2.2: each step solves (I − Δt A) u_{k+1} = u_k + Δt b exactly",
          "[grade][02-spring-stability][ex2.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 50; ++trial) {
    const auto spring = kit::test::random_spring(rng);
    const double dt = kit::test::uniform(rng, 1e-4, 1.0);
    INFO(kit::test::describe(spring) << ", dt = " << dt);
    kit::Mat2 a;  // built here from the physics, not from ex 2.1
    a << 0, 1, -spring.stiffness / spring.mass, -spring.damping / spring.mass;
    const kit::Vec2 b(0, spring.stiffness * spring.rest_length / spring.mass);
    const kit::Vec2 u(kit::test::uniform(rng, -3, 3), kit::test::uniform(rng, -3, 3));
    const kit::Vec2 next = kit::implicit_euler_spring_step(spring, u, dt);
    const kit::Vec2 residual = (kit::Mat2::Identity() - dt * a) * next - (u + dt * b);
    CHECK(residual.norm() <= 1e-10 * (1 + u.norm() + dt * b.norm()));
  }
}

TEST_CASE("ex 2.2: the energy falls every step, for any Δt, even at ω·Δt = 1e4, and x settles at L0",
          "[grade][02-spring-stability][ex2.2]") {
  kit::Spring spring;  // undamped: only the scheme can remove energy
  spring.stiffness = 100, spring.mass = 1, spring.rest_length = 0.5;
  for (double dt : {1e-3, 0.1, 1.0, 1e3}) {
    INFO("dt = " << dt);
    const kit::Vec2 start(1.5, 2.0);
    kit::Vec2 u = start;
    for (int k = 0; k < 200; ++k) {
      const kit::Vec2 next = kit::implicit_euler_spring_step(spring, u, dt);
      CHECK(spring.energy(next) <= spring.energy(u));  // 0 once it has settled exactly
      u = next;
    }
    CHECK(spring.energy(u) < spring.energy(start));
    if (dt >= 1.0) CHECK(u[0] == Approx(0.5).margin(1e-9));
  }
}

TEST_CASE("ex 2.2: implicit Euler on the spring is first order", "[grade][02-spring-stability][ex2.2]") {
  kit::Spring spring;
  spring.damping = 3.0;
  const kit::Vec2 u0(1.4, 0.0);
  auto error = [&](long n) {
    kit::Vec2 u = u0;
    for (long k = 0; k < n; ++k) u = kit::implicit_euler_spring_step(spring, u, 1.0 / double(n));
    return std::abs(u[0] - kit::spring_motion(spring, u0, 1.0)[0]);
  };
  CHECK(std::log2(error(4000) / error(8000)) == Approx(1.0).margin(0.05));
}
