// ex 4.3: the PI step-size update of Hairer's dopri5.f (pi_controller.hpp).
#include <cmath>
#include <limits>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "pi_controller.hpp"

TEST_CASE("ex 4.3: an accepted step's factor is safety·err^(−α)·prev^β, clamped to [0.2, 10]",
          "[grade][04-adaptive-rk][ex4.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 100; ++trial) {
    kit::PiController c;
    const double previous = std::exp(kit::test::uniform(rng, std::log(1e-4), 0.0));
    kit::remember_accepted(c, previous);
    const double err = std::exp(kit::test::uniform(rng, std::log(1e-12), 0.0));
    // dopri5.f: FAC = err^EXPO1 / FACOLD^BETA; FAC = max(1/FAC2, min(1/FAC1, FAC/SAFE)); HNEW = H/FAC.
    const double fac =
        std::max(1.0 / 10, std::min(1.0 / 0.2, std::pow(err, 0.17) / std::pow(previous, 0.04) / 0.9));
    INFO("err = " << err << ", previous = " << previous);
    CHECK(kit::pi_step_factor(c, err) == Approx(1.0 / fac).epsilon(1e-12));
  }
}

TEST_CASE("ex 4.3: a rejected step shrinks by max(0.2, safety·err^(−α)), never grows",
          "[grade][04-adaptive-rk][ex4.3]") {
  const kit::PiController c;
  for (double err : {1.0001, 2.0, 10.0, 1e3, 1e12, std::numeric_limits<double>::infinity()}) {
    INFO("err = " << err);
    const double expected = std::max(0.2, 0.9 * std::pow(err, -0.17));
    CHECK(kit::pi_step_factor(c, err) == Approx(expected).epsilon(1e-12));
    CHECK(kit::pi_step_factor(c, err) < 1.0);
  }
}

TEST_CASE("ex 4.3: the memory term: a smaller previous error allows less growth",
          "[grade][04-adaptive-rk][ex4.3]") {
  kit::PiController calm, rough;
  kit::remember_accepted(calm, 0.5);
  kit::remember_accepted(rough, 1e-3);
  CHECK(kit::pi_step_factor(rough, 0.1) < kit::pi_step_factor(calm, 0.1));
}
