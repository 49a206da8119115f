#include <cmath>

#include <catch2/catch.hpp>

#include <kit/free_fall.hpp>

TEST_CASE("the free-fall model's closed forms differ from the exact parabola by ∓k/2·Δt²·g") {
  kit::FreeFall fall;
  fall.x0 = 3.0, fall.v0 = 4.0, fall.g = -9.81;
  const double dt = 0.05;
  for (long k : {0L, 1L, 7L, 100L}) {
    const double exact = fall.position(double(k) * dt);
    CHECK(fall.explicit_euler_position(k, dt) - exact == Approx(-0.5 * double(k) * dt * dt * fall.g).margin(1e-12));
    CHECK(fall.implicit_euler_position(k, dt) - exact == Approx(0.5 * double(k) * dt * dt * fall.g).margin(1e-12));
    CHECK(fall.euler_error(k, dt) == Approx(0.5 * double(k) * dt * dt * 9.81).margin(1e-15));
  }
}

TEST_CASE("the free-fall model is u' = A u + b with A = [[0,1],[0,0]], b = (0, g)") {
  kit::FreeFall fall;
  fall.g = 2.5;
  const auto s = fall.affine();
  const kit::Vec2 u(1.0, -3.0);
  CHECK((s(0.0, u) - fall(0.0, u)).norm() == 0.0);
  CHECK(fall(0.0, u) == kit::Vec2(-3.0, 2.5));
  CHECK(fall.exact_state(2.0) == kit::Vec2(fall.position(2.0), fall.velocity(2.0)));
}
