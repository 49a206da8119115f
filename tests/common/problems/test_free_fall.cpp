#include <cmath>

#include <kit_catch.hpp>

#include <kit/problems/free_fall.hpp>

TEST_CASE(
    "the free-fall closed forms are where Euler loops run here actually land, k/2·Δt²·|g| off the parabola") {
  kit::FreeFall fall;
  fall.x0 = 3.0, fall.v0 = 4.0, fall.g = -9.81;
  const double dt = 0.05;
  // Independent of the model: the lecture's explicit loop (x with the old v, then v), and
  // implicit Euler on free fall, which is v first, then x with the new v.
  double xe = fall.x0, ve = fall.v0, xi = fall.x0, vi = fall.v0;
  for (long k = 0; k <= 100; ++k) {
    if (k == 0 || k == 1 || k == 7 || k == 100) {
      INFO("k = " << k);
      const double exact = fall.position(double(k) * dt);
      CHECK(fall.explicit_euler_position(k, dt) == Approx(xe).margin(1e-12));
      CHECK(fall.implicit_euler_position(k, dt) == Approx(xi).margin(1e-12));
      CHECK(fall.euler_error(k, dt) == Approx(xe - exact).margin(1e-12));  // g < 0: explicit above
      CHECK(fall.euler_error(k, dt) == Approx(exact - xi).margin(1e-12));  // implicit below
    }
    xe += dt * ve, ve += dt * fall.g;
    vi += dt * fall.g, xi += dt * vi;
  }
  // By hand: 7 steps of 0.05 s under |g| = 9.81 m/s²: 7/2 · 0.0025 · 9.81 = 0.0858375 m, and
  // 100 steps: 50 · 0.0025 · 9.81 = 1.22625 m. The lecture's k/2·Δt² (no |g|) would give 0.00875 m.
  CHECK(fall.euler_error(7, dt) == Approx(0.0858375).epsilon(1e-14));
  CHECK(fall.euler_error(100, dt) == Approx(1.22625).epsilon(1e-14));
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
