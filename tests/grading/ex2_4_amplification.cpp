// ex 2.4: the amplification factor R(z) of each scheme (amplification.hpp).
#include <cmath>
#include <complex>

#include <kit_catch.hpp>

#include "amplification.hpp"
#include "cases.hpp"

using kit::Scheme;
using C = std::complex<double>;

TEST_CASE("ex 2.4: R(z) is 1 + z, 1/(1 − z), 1 + z + z²/2 and the degree-4 Taylor polynomial of e^z",
          "[grade][02-spring-stability][ex2.4]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 50; ++trial) {
    const C z(kit::test::uniform(rng, -3, 1), kit::test::uniform(rng, -3, 3));
    INFO("z = " << z);
    CHECK(std::abs(kit::amplification_factor(Scheme::explicit_euler, z) - (1.0 + z)) < 1e-12);
    CHECK(std::abs(kit::amplification_factor(Scheme::implicit_euler, z) - 1.0 / (1.0 - z)) < 1e-12);
    CHECK(std::abs(kit::amplification_factor(Scheme::midpoint, z) - (1.0 + z + z * z / 2.0)) < 1e-12);
    const C taylor = 1.0 + z + z * z / 2.0 + z * z * z / 6.0 + z * z * z * z / 24.0;
    CHECK(std::abs(kit::amplification_factor(Scheme::rk4, z) - taylor) < 1e-11 * (1 + std::abs(taylor)));
  }
}

TEST_CASE("ex 2.4: on the imaginary axis, explicit Euler grows by sqrt(1 + y²) and implicit Euler shrinks by "
          "its inverse",
          "[grade][02-spring-stability][ex2.4]") {
  for (double y : {0.01, 0.2, 1.0, 3.0, 100.0}) {
    CHECK(std::abs(kit::amplification_factor(Scheme::explicit_euler, C(0, y))) ==
          Approx(std::sqrt(1 + y * y)).epsilon(1e-14));
    CHECK(std::abs(kit::amplification_factor(Scheme::implicit_euler, C(0, y))) ==
          Approx(1 / std::sqrt(1 + y * y)).epsilon(1e-14));
  }
}

TEST_CASE("ex 2.4: RK4 covers the imaginary axis up to 2√2 and no further",
          "[grade][02-spring-stability][ex2.4]") {
  CHECK(std::abs(kit::amplification_factor(Scheme::rk4, C(0, 2.82))) < 1.0);
  CHECK(std::abs(kit::amplification_factor(Scheme::rk4, C(0, 2.84))) > 1.0);
}

TEST_CASE("ex 2.4: symplectic Euler has no scalar R(z), and says so", "[grade][02-spring-stability][ex2.4]") {
  CHECK_THROWS_AS(kit::amplification_factor(Scheme::symplectic_euler, C(0, 1)), std::invalid_argument);
}
