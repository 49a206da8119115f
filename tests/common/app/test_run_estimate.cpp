// Estimates of a run's cost from its counts, said before it starts (run_estimate.hpp).
#include <kit_catch.hpp>

#include <sstream>

#include <kit/app/run_estimate.hpp>
#include <kit/base/usage.hpp>
#include <kit/ode/step_budget.hpp>

TEST_CASE("an estimate is its steps times the cost of a step; memory and time for a person to read") {
  const kit::RunEstimate e{2e9, 3e-9, 4e7};
  CHECK(e.seconds() == Approx(6));
  CHECK(kit::describe(e) == "about 2e+09 steps: about 6 s and 40 MB");
  CHECK(kit::describe_bytes(5e5) == "under 1 MB");
  CHECK(kit::describe_bytes(2.1e9) == "2.1 GB");
  CHECK(kit::describe_bytes(3e13) == "30 TB");
  CHECK(kit::describe_bytes(1.6e16) == "16 PB");
  CHECK(kit::describe_bytes(1.2e11) == "120 GB");  // no exponent: a person reads it at a glance
  CHECK(kit::describe_bytes(999.7e9) == "1 TB");   // the unit follows the rounding
  CHECK(kit::describe_bytes(999.4e6) == "999 MB");
  CHECK(kit::describe_bytes(9.96e9) == "10 GB");
  CHECK_FALSE(kit::over_limits(e));
  CHECK(kit::over_limits({1e12, 1e-9, 0}));   // 1000 s: over 10 min
  CHECK(kit::over_limits({1e3, 1e-9, 5e9}));  // 5 GB: over 4 GB
  CHECK(kit::over_limits({1e3, 1e-9, NAN}));  // an unknown amount is never taken to fit
}

TEST_CASE("the round-off sweep's estimate counts its runs: every count in double, those in float's budget "
          "twice more") {
  const auto doubles = kit::budget_sweep(1.0, 0.1, 1e-9, 2'000'000'000);
  const auto floats = kit::budget_sweep(1.0, 0.1, 1e-7, 100'000'000);
  double in_double = 0, in_float = 0;
  for (long m : doubles.counts(4)) {
    in_double += double(m);
    if (m <= floats.most_steps()) in_float += double(m);
  }
  const kit::RoundoffCosts costs{1e-9, 2e-9, 10e-9};
  const kit::RunEstimate e = kit::roundoff_estimate(doubles, floats, costs);
  CHECK(e.steps == in_double + 2 * in_float);
  CHECK(e.seconds() == Approx(1e-9 * in_double + 12e-9 * in_float));
  CHECK(e.work == Approx(e.seconds() / 1e-9));  // the progress line counts explicit double steps
  CHECK(
      e.steps ==
      Approx(1'000'000'000 / (1 - std::pow(10, -0.25)) + 2 * 1e7 / (1 - std::pow(10, -0.25))).epsilon(0.01));
  // At the budget (T = 10 s: the finest double run is 2e9 steps), the counts grow with it.
  const auto raised = kit::budget_sweep(10.0, 0.1, 1e-9, 2'000'000'000);
  CHECK(kit::roundoff_estimate(raised, floats, costs).steps > 2 * e.steps);
}

TEST_CASE("announcing: stored always, printed when long or large, refused with the flags and the estimate "
          "when it cannot fit") {
  nlohmann::json summary;
  std::ostringstream text;
  kit::Report report(text, summary);
  kit::announce_run(report, "quick", "A short run", {1e6, 1e-9, 1e3}, "--n 1e6");
  CHECK(text.str().empty());
  CHECK(summary["quick"]["estimate"]["steps"] == 1e6);
  CHECK(summary["quick"]["estimate"]["announced"] == false);

  kit::announce_run(report, "long", "The sweep", {5e9, 1e-9, 1e3}, "--t-end 10 s");
  CHECK(text.str() == "\nThe sweep takes about 5e+09 steps: about 5 s and under 1 MB.\n");
  CHECK(summary["long"]["estimate"]["seconds"] == Approx(5));
  CHECK(summary["long"]["estimate"]["announced"] == true);

  kit::announce_run(report, "large", "The record", {1e6, 1e-9, 1e9}, "--t-end 10 s");
  CHECK_THAT(text.str(), ContainsSubstring("The record takes about 1e+06 steps: under a second and 1 GB."));

  try {
    kit::announce_run(report, "huge", "The round-off sweep", {2.3e12, 1e-9, 1e3},
                      "--t-end 1 s, --dt-min 1e-12 s");
    FAIL("not refused");
  } catch (const kit::UsageError& e) {
    CHECK_THAT(e.what(), ContainsSubstring("--t-end 1 s, --dt-min 1e-12 s") &&
                             ContainsSubstring("about 2.3e+12 steps: about 38 min and under 1 MB") &&
                             ContainsSubstring("over the limit of 10 min and 4 GB"));
  }
  CHECK_FALSE(summary.contains("huge"));  // refused before anything is recorded

  // Over the memory only: the advice is about memory, not about steps.
  CHECK_THROWS_WITH(kit::announce_run(report, "big", "The store", {1, 1e-9, 1.2e11}, "--max-particles 1e9"),
                    ContainsSubstring("about 1 steps: under a second and 120 GB") &&
                        ContainsSubstring("choose values that ask for less memory"));
  CHECK_THROWS_WITH(kit::announce_run(report, "both", "The sweep", {2.3e12, 1e-9, 1.2e11}, "--t-end 1 s"),
                    ContainsSubstring("ask for fewer steps and less memory"));
}
