// The work-precision harness: every (method, tolerance) run once per round, in a rotating
// order, its counts kept and its error measured against the reference. Counts, never times.
#include <cmath>
#include <vector>

#include <kit_catch.hpp>

#include <kit/ode/work_precision.hpp>
#include <kit/ode/work_precision_methods.hpp>
#include <kit/problems/adaptive_rk_models.hpp>

namespace {
// A method whose error is its tolerance and whose cost is 1/tolerance, calling `calls` each run.
kit::WorkMethod<2> fake(const char* label, std::vector<double> tolerances, int& calls) {
  return {label, "", std::move(tolerances), [&calls](double tol) {
            ++calls;
            return kit::WorkRun<2>{kit::Vec2(1.0 + tol, -2.0), long(std::lround(1 / tol)), 10L, std::nullopt};
          }};
}
}  // namespace

TEST_CASE(
    "the harness returns a curve per method, in order, with the counts each run returned and its max error") {
  int calls_a = 0, calls_b = 0;
  const auto curves = kit::measure_work_precision<2>(
      {fake("a", {1e-2, 1e-4}, calls_a), fake("b", {1e-3}, calls_b)}, kit::Vec2(1.0, -2.0), {3, 0.0});
  REQUIRE(curves.size() == 2);
  CHECK(curves[0].label == "a");
  REQUIRE(curves[0].points.size() == 2);
  CHECK(curves[0].points[1].tolerance == 1e-4);
  CHECK(curves[0].points[1].error == Approx(1e-4).epsilon(1e-9));
  CHECK(curves[0].points[1].rhs_evals == 10'000);
  CHECK(curves[0].points[1].accepted == 10L);
  CHECK_FALSE(curves[0].points[1].rejected);
  CHECK_FALSE(curves[0].points[1].attempts());  // unknown rejected steps: unknown attempts
  CHECK(curves[1].points[0].rhs_evals == 1000);
  CHECK(calls_a == 2 * 3);  // one call per tolerance and round when min_seconds = 0
  CHECK(calls_b == 3);
  CHECK(curves[0].points[0].seconds >= 0);
  // 1e-3 lies halfway (in logs) between the points (100, 1e-2) and (10000, 1e-4): 1000 evaluations.
  CHECK(curves[0].evaluations_to_reach(1e-3) == Approx(1000).epsilon(1e-9));
  CHECK(std::isnan(curves[0].evaluations_to_reach(1e-5)));
}

TEST_CASE("fastest_interleaved starts round r with run r mod K, so each run follows each other in turn") {
  std::vector<int> order;
  std::vector<std::function<void()>> runs;
  for (int i = 0; i < 3; ++i) runs.push_back([&order, i] { order.push_back(i); });
  const auto seconds = kit::fastest_interleaved(runs, {2, 0.0});
  CHECK(order == std::vector<int>{0, 1, 2, 1, 2, 0});
  CHECK(seconds.size() == 3);
}

TEST_CASE("the peers say what they know: GSL accepted and rejected steps, Boost.Odeint accepted ones only") {
  const kit::Vec4 y0 = kit::Arenstorf::initial_state();
  const double t1 = kit::Arenstorf::period;
  const auto curves = kit::measure_work_precision<4>(
      {kit::gsl_method(kit::GslStepper::rkck, kit::Arenstorf{}, 0.0, y0, t1, 1e-4, {1e-8}),
       kit::boost_dopri5_method(kit::Arenstorf{}, 0.0, y0, t1, 1e-4, {1e-8})},
      y0, {1, 0.0});
  const kit::WorkPoint& gsl = curves[0].points[0];
  CHECK(gsl.rhs_evals == 2383);  // ANCHORS.md
  REQUIRE(gsl.attempts());
  CHECK(gsl.rhs_evals == 1 + 6 * *gsl.attempts());  // rkck: 6 per attempt, accepted or rejected
  const kit::WorkPoint& boost = curves[1].points[0];
  CHECK(boost.rhs_evals == 2491);  // ANCHORS.md
  REQUIRE(boost.accepted);
  CHECK(6 * *boost.accepted < boost.rhs_evals);  // 6 per attempt: fewer accepted steps than that
  CHECK_FALSE(boost.rejected);
}
