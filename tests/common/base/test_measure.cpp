#include <cmath>

#include <kit_catch.hpp>

#include <kit/base/measure.hpp>

TEST_CASE("fit_loglog recovers the exponent and constant of err = C·Δt^p exactly") {
  std::vector<double> dt, err;
  for (double h : {1e-1, 3e-2, 1e-2, 3e-3, 1e-3}) dt.push_back(h), err.push_back(7.0 * std::pow(h, 2.5));
  const auto fit = kit::fit_loglog(dt, err);
  CHECK(fit.slope == Approx(2.5).epsilon(1e-12));
  CHECK(fit.intercept == Approx(std::log10(7.0)).epsilon(1e-12));
}

TEST_CASE("fit_loglog refuses data it cannot take a log of") {
  const std::vector<double> dt{0.1, 0.01}, err{1e-3, 0.0};
  CHECK_THROWS_WITH(kit::fit_loglog(dt, err), ContainsSubstring("positive"));
  CHECK_THROWS(kit::fit_loglog(std::vector<double>{0.1}, std::vector<double>{1.0}));
}

TEST_CASE("geometric_counts spreads whole step counts evenly per decade, without repeats") {
  const auto counts = kit::geometric_counts(10, 10'000, 4);
  REQUIRE(counts.size() == 13);
  CHECK(counts.front() == 10);
  CHECK(counts.back() == 10'000);
  CHECK(counts[4] == 100);
  for (std::size_t i = 1; i < counts.size(); ++i) CHECK(counts[i] > counts[i - 1]);
  const auto dense = kit::geometric_counts(1, 3, 10);  // rounding would repeat 1 and 2
  CHECK(dense == std::vector<long>{1, 2, 3});
}

TEST_CASE("argmin skips NaN and returns the first of equal minima") {
  const std::vector<double> v{3.0, NAN, 1.0, 1.0, 2.0};
  CHECK(kit::argmin(v) == 2);
  CHECK_THROWS(kit::argmin(std::vector<double>{NAN}));
}

TEST_CASE("agrees accepts exactly the stated relative and absolute budget") {
  CHECK(kit::agrees(1.0 + 1e-10, 1.0, 1e-9, 0.0));
  CHECK_FALSE(kit::agrees(1.0 + 1e-8, 1.0, 1e-9, 0.0));
  CHECK(kit::agrees(1e-13, 0.0, 1e-9, 1e-12));
  CHECK_FALSE(kit::agrees(NAN, 1.0, 1e-9, 1e-12));
}

TEST_CASE(
    "cost_to_reach interpolates a work-precision curve on log-log axes, and says NaN when never reached") {
  const std::vector<double> cost{100, 1000, 10000}, error{1e-2, 1e-4, 1e-6};  // error ∝ cost^−2
  CHECK(kit::cost_to_reach(cost, error, 1e-3) == Approx(std::sqrt(1e5)).epsilon(1e-12));
  CHECK(kit::cost_to_reach(cost, error, 1e-2) == Approx(100));
  CHECK(std::isnan(kit::cost_to_reach(cost, error, 1e-9)));
  const std::vector<double> shuffled_cost{10000, 100, 1000}, shuffled_error{1e-6, 1e-2, 1e-4};
  CHECK(kit::cost_to_reach(shuffled_cost, shuffled_error, 1e-5) == Approx(std::sqrt(1e7)).epsilon(1e-12));
}
