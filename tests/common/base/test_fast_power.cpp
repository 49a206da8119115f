// FastPower: x^p from tables, against std::pow, with the error bound its header states.
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include <kit_catch.hpp>

#include <kit/base/fast_power.hpp>

namespace {
// |p(p−1)(p−2)|·(w/2)³/(9√3), w = 1/256: the interpolation bound, plus a few rounding units.
double bound(double p) {
  return std::abs(p * (p - 1) * (p - 2)) * std::pow(1.0 / 512, 3) / (9 * std::sqrt(3.0)) + 8e-16;
}
}  // namespace

TEST_CASE("FastPower matches std::pow within its stated bound over 2^±120") {
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> exponent(-120.0, 120.0);
  for (double p : {-0.085, 0.02, -0.2, 0.5, -1.0, 1.0, 2.0}) {
    const kit::FastPower power(p);
    double worst = 0;
    for (int i = 0; i < 200000; ++i) {
      const double x = std::exp2(exponent(rng));
      worst = std::max(worst, std::abs(power(x) / std::pow(x, p) - 1));
    }
    INFO("p = " << p << ", worst relative error " << worst << ", bound " << bound(p));
    CHECK(worst <= bound(p));
    if (p == -0.085) CHECK(worst < 1e-10);  // DOPRI5's exponent: the step-size factor to 10 digits
    if (bound(p) > 1e-12) CHECK(worst >= 0.25 * bound(p));  // the bound is tight, not vacuous
  }
}

TEST_CASE("FastPower at the edges of its tables, outside them, and for a bad exponent") {
  const kit::FastPower cube(3.0), root(-0.085);
  CHECK(cube(8.0) == Approx(512.0).epsilon(1e-15));
  CHECK(root(1.0) == Approx(1.0).epsilon(1e-15));
  // The first and last exponents in the table, and the first ones past it (the fallback).
  for (double x : {std::ldexp(1.0, -128), std::nextafter(std::ldexp(1.0, 128), 0.0), std::ldexp(1.0, -129),
                   std::ldexp(1.0, 128), 1e-300, 5e-324, 1e300}) {
    INFO("x = " << x);
    CHECK(root(x) == Approx(std::pow(x, -0.085)).epsilon(1e-10));
    CHECK(cube(x) == Approx(std::pow(x, 3.0)).epsilon(1e-9));
  }
  for (double x : {0.0, -2.0, std::numeric_limits<double>::infinity()}) {
    INFO("x = " << x);
    CHECK((root(x) == std::pow(x, -0.085) || (std::isnan(root(x)) && std::isnan(std::pow(x, -0.085)))));
  }
  CHECK(std::isnan(root(std::numeric_limits<double>::quiet_NaN())));
  CHECK(root.scaled(4.0, 3.0) == Approx(3.0 * std::pow(4.0, -0.085)).epsilon(1e-15));
  CHECK_THROWS_AS(kit::FastPower(8.5), std::invalid_argument);
  CHECK_THROWS_AS(kit::FastPower(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
}

TEST_CASE("fast_power builds one table per exponent and hands it out again") {
  const kit::FastPower& a = kit::fast_power(-0.085);
  const kit::FastPower& b = kit::fast_power(0.02);
  CHECK(&kit::fast_power(-0.085) == &a);
  CHECK(&kit::fast_power(0.02) == &b);
  CHECK(a.exponent() == -0.085);
}
