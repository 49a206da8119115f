// A sweep over Δt = T/m within a budget of steps (step_budget.hpp).
#include <kit_catch.hpp>

#include <kit/ode/step_budget.hpp>

TEST_CASE("a sweep within its step budget runs exactly as asked") {
  const auto s = kit::budget_sweep(1.0, 0.1, 1e-9, 2'000'000'000);
  CHECK_FALSE(s.raised());
  CHECK(s.dt_min == 1e-9);
  CHECK(s.fewest_steps() == 10);
  CHECK(s.most_steps() == 1'000'000'000);
  const auto counts = s.counts(4);
  CHECK(counts.front() == 10);
  CHECK(counts.back() == 1'000'000'000);
  CHECK(counts.size() == 33);  // 8 decades, 4 a decade, both ends
}

TEST_CASE("a sweep past its step budget raises its smallest step to T/budget; no run exceeds the budget") {
  const auto s = kit::budget_sweep(6.721, 0.1, 1e-9, 2'000'000'000);  // 6.7e9 steps asked
  CHECK(s.raised());
  CHECK(s.dt_min_requested == 1e-9);
  CHECK(s.dt_min == Approx(6.721 / 2e9).epsilon(1e-15));
  CHECK(s.fewest_steps() == 67);
  CHECK(s.most_steps() == 2'000'000'000);
  CHECK(s.counts(4).back() == 2'000'000'000);
}

TEST_CASE("a sweep shorter than its largest step still has one run, and bad ranges are refused") {
  const auto s = kit::budget_sweep(1e-3, 0.1, 1e-5, 100);
  CHECK(s.fewest_steps() == 1);
  CHECK(s.most_steps() == 100);  // 1e-3/1e-5 = 100, exactly the budget: not raised
  CHECK_FALSE(s.raised());
  CHECK_THROWS_AS(kit::budget_sweep(1.0, 1e-3, 0.1, 100), std::invalid_argument);  // dt_min > dt_max
  CHECK_THROWS_AS(kit::budget_sweep(0.0, 0.1, 1e-3, 100), std::invalid_argument);
  CHECK_THROWS_AS(kit::budget_sweep(1.0, 0.1, 1e-3, 0), std::invalid_argument);
}
