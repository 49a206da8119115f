#include <cmath>
#include <limits>

#include <kit_catch.hpp>

#include <kit/ode/reference_solver.hpp>
#include <kit/problems/adaptive_rk_models.hpp>
#include <kit/problems/free_fall.hpp>

TEST_CASE("the GSL reference matches free fall's closed form to 1e-10") {
  kit::FreeFall fall;
  fall.x0 = 100.0, fall.v0 = 12.0;
  const std::vector<double> times{0.5, 1.0, 2.0, 4.5};
  kit::Stats stats;
  const auto states = kit::reference_solution(fall, 0.0, fall.initial_state(), times, {}, &stats);
  for (std::size_t i = 0; i < times.size(); ++i) {
    CHECK(states.u[i][0] == Approx(fall.position(times[i])).margin(1e-10));
    CHECK(states.u[i][1] == Approx(fall.velocity(times[i])).margin(1e-10));
  }
  CHECK(stats.rhs_evals > 0);
}

TEST_CASE("the GSL reference matches a harmonic oscillator over ten periods to 1e-10") {
  const double omega = 2.0;
  auto oscillator = [omega](double, const kit::Vec2& u) { return kit::Vec2(u[1], -omega * omega * u[0]); };
  const double t_end = 10 * 2 * M_PI / omega;
  const auto states = kit::reference_solution(oscillator, 0.0, kit::Vec2(1.0, 0.0), {t_end});
  CHECK(states.u[0][0] == Approx(std::cos(omega * t_end)).margin(1e-10));
  CHECK(states.u[0][1] == Approx(-omega * std::sin(omega * t_end)).margin(1e-10));
}

TEST_CASE("a NaN from the right-hand side is a SolverError, never an accepted step or an abort") {
  auto poisoned = [](double t, const kit::Vec2& u) {
    return kit::Vec2(u[1], t > 0.5 ? std::numeric_limits<double>::quiet_NaN() : -1.0);
  };
  CHECK_THROWS_AS(kit::reference_solution(poisoned, 0.0, kit::Vec2(0.0, 0.0), {1.0}), kit::SolverError);
  CHECK_THROWS_WITH(kit::reference_solution(poisoned, 0.0, kit::Vec2(0.0, 0.0), {1.0}),
                    ContainsSubstring("NaN"));
}

TEST_CASE("an exception thrown by the right-hand side crosses GSL unchanged") {
  auto throwing = [](double, const kit::Vec2&) -> kit::Vec2 {
    throw std::out_of_range("model left its domain");
  };
  CHECK_THROWS_AS(kit::reference_solution(throwing, 0.0, kit::Vec2(0.0, 0.0), {1.0}), std::out_of_range);
}

TEST_CASE("a GSL failure (step budget exhausted) is a SolverError naming the stepper and times") {
  kit::GslOptions options;
  options.max_steps = 3;
  auto fast = [](double, const kit::Vec2& u) { return kit::Vec2(u[1], -1e6 * u[0]); };
  CHECK_THROWS_AS(kit::reference_solution(fast, 0.0, kit::Vec2(1.0, 0.0), {10.0}, options), kit::SolverError);
  CHECK_THROWS_WITH(kit::reference_solution(fast, 0.0, kit::Vec2(1.0, 0.0), {10.0}, options),
                    ContainsSubstring("rk8pd") && ContainsSubstring("t = 0"));
}

TEST_CASE(
    "Stats::steps counts the accepted steps of every sample interval; rejected steps are counted apart") {
  // u' = (1, 0) is integrated exactly, so GSL's control grows h by its cap, 5, after each step:
  // 0.1 to t = 0.1, then 0.4 (cut to reach the sample at 0.5), then 0.5 (cut to reach 1.0).
  kit::GslOptions options;
  options.stepper = kit::GslStepper::rkck;
  options.h0 = 0.1;
  kit::Stats stats;
  const auto line = [](double, const kit::Vec2&) { return kit::Vec2(1.0, 0.0); };
  const auto states = kit::reference_solution(line, 0.0, kit::Vec2(0.0, 0.0), {0.5, 1.0}, options, &stats);
  CHECK(states.u[1][0] == Approx(1.0).margin(1e-14));
  CHECK(stats.steps == 3);  // GSL's driver counter, reset at each sample, would say 1
  CHECK(stats.rejected == 0);
  CHECK(stats.rhs_evals == 1 + 6 * 3);  // rkck: 5 stages and f at the new point, reused as the next k1
}

TEST_CASE("GSL rkck on Arenstorf at 1e-8 rejects steps, and spends 6 evaluations on each attempt, accepted "
          "or not") {
  kit::GslOptions options;
  options.stepper = kit::GslStepper::rkck;
  options.rtol = options.atol = 1e-8;
  options.h0 = 1e-4;
  kit::Stats stats;
  kit::reference_solution(kit::Arenstorf{}, 0.0, kit::Arenstorf::initial_state(), {kit::Arenstorf::period},
                          options, &stats);
  CHECK(stats.rhs_evals == 2383);  // ANCHORS.md: GSL rkck, tol 1e-8
  CHECK(stats.rejected > 0);
  CHECK(stats.rhs_evals == 1 + 6 * (stats.steps + stats.rejected));
}
