// ex 4.1: the lecture's step-doubling controller, guarded (step_doubling.hpp).
#include <algorithm>
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "step_doubling.hpp"

namespace {
using V = kit::Vec<1>;
// y' = −y, y(t) = e^{−t}, stepped by explicit Euler written out here: a grade of ex 4.1 never
// depends on the student's ex 1.1.
const auto euler = [](double, const V& y, double dt) { return V(y[0] - dt * y[0]); };
}  // namespace

TEST_CASE(
    "ex 4.1: guarded step doubling reaches t_end, keeps every accepted e below E_max, and lands on t_end",
    "[grade][04-adaptive-rk][ex4.1]") {
  kit::StepDoubling options;
  options.e_min = 1e-6, options.e_max = 1e-4, options.dt0 = 0.5;
  const auto run = kit::step_doubling(euler, 0.0, V(1.0), 3.0, options);
  REQUIRE(run.status == kit::RunStatus::finished);
  CHECK(run.accepted.t.back() == 3.0);
  CHECK(run.accepted.u.back()[0] == Approx(std::exp(-3.0)).epsilon(0.05));
  CHECK(run.stats.steps == long(run.step_sizes.size()));
  // Recompute each accepted step's estimate: one Euler step of h against two of h/2. The
  // largest is checked once, so the number of assertions does not depend on how many steps a
  // correct controller takes (the grader expects a fixed count per case).
  double largest = 0;
  for (std::size_t i = 0; i < run.step_sizes.size(); ++i) {
    const double h = run.step_sizes[i];
    const V y = run.accepted.u[i];
    largest = std::max(largest, std::abs(euler(0, y, h)[0] - euler(0, euler(0, y, h / 2), h / 2)[0]));
  }
  CHECK(run.stats.steps > 0);
  CHECK(largest <= options.e_max);
}

TEST_CASE("ex 4.1: the step grows when the error is small and shrinks when it is large",
          "[grade][04-adaptive-rk][ex4.1]") {
  kit::StepDoubling options;
  options.e_min = 1e-7, options.e_max = 1e-5, options.dt0 = 1e-5;  // far too small at first
  const auto run = kit::step_doubling(euler, 0.0, V(1.0), 1.0, options);
  REQUIRE(run.status == kit::RunStatus::finished);
  CHECK(run.step_sizes[5] >= 8 * run.step_sizes[0]);  // doubled at least 3 times in 5 steps
  kit::StepDoubling coarse = options;
  coarse.dt0 = 0.9;  // far too large: rejected, halved
  const auto shrunk = kit::step_doubling(euler, 0.0, V(1.0), 1.0, coarse);
  CHECK(shrunk.stats.rejected >= 3);
  CHECK(shrunk.step_sizes.front() < 0.9 / 4);
}

TEST_CASE("ex 4.1: the lecture's loop with E_max/E_min < 2^(p+1) is reported as trapped, not a hang",
          "[grade][04-adaptive-rk][ex4.1]") {
  kit::StepDoubling options;
  options.e_min = 4e-7, options.e_max = 1e-6, options.dt0 = 0.1, options.guarded = false,
  options.max_retries = 100;
  const auto lecture = kit::step_doubling(euler, 0.0, V(1.0), 5.0, options);
  CHECK(lecture.status == kit::RunStatus::trapped);
  CHECK_THAT(lecture.message, ContainsSubstring("trapped"));
  options.guarded = true;
  CHECK(kit::step_doubling(euler, 0.0, V(1.0), 5.0, options).status == kit::RunStatus::finished);
}

TEST_CASE("ex 4.1: each trial costs three steps of the method: one of dt and two of dt/2",
          "[grade][04-adaptive-rk][ex4.1]") {
  long calls = 0;
  const auto counted = [&](double t, const V& y, double dt) {
    ++calls;
    return euler(t, y, dt);
  };
  kit::StepDoubling options;
  options.e_min = 1e-6, options.e_max = 1e-4, options.dt0 = 0.3;
  const auto run = kit::step_doubling(counted, 0.0, V(1.0), 2.0, options);
  CHECK(calls == 3 * (run.stats.steps + run.stats.rejected));
}
