// The production DOPRI5 (common/include/kit/ode/dopri5.hpp): Hairer's counts, closed forms, dense
// output, and failures reported rather than accepted. It includes no student file: where a test
// needs a method, it is written here, from the textbook formula.
#include <cmath>
#include <limits>
#include <random>

#include <kit_catch.hpp>

#include <kit/ode/dopri5.hpp>
#include <kit/ode/dopri5_work_method.hpp>
#include <kit/ode/embedded_run.hpp>
#include <kit/ode/pi_step_control.hpp>
#include <kit/problems/adaptive_rk_models.hpp>
#include <kit/problems/free_fall.hpp>
#include <kit/problems/spring.hpp>

namespace {
// dopri5.f's step-size factor, transcribed: FAC11 = err^EXPO1, FAC = FAC11 / FACOLD^BETA,
// FAC = max(FACC2, min(FACC1, FAC / SAFE)), HNEW = H / FAC; after a rejection
// HNEW = H / min(FACC1, FAC11 / SAFE). EXPO1 = 0.2 − 0.75·BETA, FACC1 = 1/0.2, FACC2 = 1/10.
double dopri5f_factor(double err, double previous, bool accepted) {
  const double beta = 0.04, fac11 = std::pow(err, 0.2 - 0.75 * beta), facold = std::max(previous, 1e-4);
  if (!accepted) return 1.0 / std::min(5.0, fac11 / 0.9);
  return 1.0 / std::max(0.1, std::min(5.0, fac11 / std::pow(facold, beta) / 0.9));
}

// One step of an embedded pair straight from its tableau (the textbook formula), for the
// general driver: stages k_i = f(t + c_i h, y + h Σ a_ij k_j); y + h Σ b_i k_i; h Σ (b_i − b̂_i) k_i.
template <class Rhs, class State>
kit::EmbeddedStep<State> tableau_step(const Rhs& f, const kit::ButcherTableau& tab, double t, const State& y,
                                      double h, const State& k1) {
  std::vector<State> k{k1};
  for (int i = 1; i < tab.stages(); ++i) {
    State yi = y;
    for (int j = 0; j < i; ++j) yi += h * double(tab.a[i][j]) * k[j];
    k.push_back(f(t + double(tab.c[i]) * h, yi));
  }
  kit::EmbeddedStep<State> out{y, State::Zero(y.size()), k.back(), tab.stages() - 1};
  for (int i = 0; i < tab.stages(); ++i) {
    out.y += h * double(tab.b[i]) * k[i];
    out.error += h * double(tab.b[i] - tab.b_hat[i]) * k[i];
  }
  return out;
}

// m x'' = K (L0 − x) − μ x' as u' = f(u), u = (x, v), written out.
auto spring_rhs(const kit::Spring& s) {
  return [s](double, const kit::Vec2& u) {
    return kit::Vec2(u[1], (s.stiffness * (s.rest_length - u[0]) - s.damping * u[1]) / s.mass);
  };
}

// The law of ex 4.3, as dopri5.f writes it, for the general driver.
double pi_factor(const kit::PiController& c, double err) {
  return dopri5f_factor(err, std::exp(c.log_previous_error), err <= 1.0);
}
}  // namespace

TEST_CASE("DOPRI5 on Arenstorf reproduces Hairer's dopri5.f: evaluations, steps, rejections, errors") {
  struct Expected {
    double tol;
    long evaluations, attempts, rejected;
    double error;
  };
  for (const Expected& e :
       {Expected{1e-6, 985, 164, 23, 4.4e-2}, {1e-8, 2161, 360, 21, 7.8e-5}, {1e-10, 5047, 841, 0, 2.4e-6}}) {
    kit::Dopri5Options o;
    o.rtol = o.atol = e.tol, o.h0 = 1e-4;
    const auto r =
        kit::dopri5(kit::Arenstorf{}, 0.0, kit::Arenstorf::initial_state(), kit::Arenstorf::period, o);
    INFO("tol = " << e.tol);
    REQUIRE(r.status == kit::RunStatus::finished);
    CHECK(r.stats.rhs_evals == e.evaluations);
    CHECK(r.stats.steps + r.stats.rejected == e.attempts);
    CHECK(r.stats.rejected == e.rejected);
    CHECK((r.y - kit::Arenstorf::initial_state()).cwiseAbs().maxCoeff() == Approx(e.error).epsilon(0.05));
  }
}

TEST_CASE("DOPRI5's fast step-size law gives dopri5.f's factors to 2e-10, with its clamps and its memory") {
  const int n = 4;  // components in the RMS norm: the control sees S = n·err²
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> log10_err(-12.0, 0.0), log10_previous(-6.0, 0.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const double err = std::pow(10.0, log10_err(rng)), previous = std::pow(10.0, log10_previous(rng)),
                 h = 0.37;
    kit::PiStepControl fast(kit::PiController{}, n);
    fast.remember_accepted(n * previous * previous);
    INFO("err = " << err << ", previous = " << previous);
    CHECK(fast.acceptable(n * err * err));
    const double expected = h * dopri5f_factor(err, previous, true);
    CHECK(fast.after_accepted(h, n * err * err, 1e9, false) == Approx(expected).epsilon(2e-10));
    // No growth right after a rejection; never above h_max.
    CHECK(fast.after_accepted(h, n * err * err, 1e9, true) == Approx(std::min(expected, h)).epsilon(2e-10));
    CHECK(fast.after_accepted(h, n * err * err, 0.5 * h, false) ==
          Approx(std::min(expected, 0.5 * h)).epsilon(2e-10));
  }
  const kit::PiController law;
  const kit::PiStepControl fast(law, n);
  for (double err : {1.0001, 2.0, 10.0, 1e3, 1e12}) {
    INFO("err = " << err);
    CHECK_FALSE(fast.acceptable(n * err * err));
    CHECK(fast.after_rejected(1.0, n * err * err) == Approx(dopri5f_factor(err, 1.0, false)).epsilon(2e-10));
  }
  for (double poisoned :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    CHECK_FALSE(fast.acceptable(poisoned));
    CHECK(fast.after_rejected(1.0, poisoned) == law.min_factor);
  }
}

TEST_CASE("DOPRI5 costs 6 evaluations per attempted step (FSAL), plus 1 at the start") {
  kit::Dopri5Options o;
  o.h0 = 1e-3;
  long calls = 0;
  const auto counted = [&](double t, const kit::Vec4& y) {
    ++calls;
    return kit::Arenstorf{}(t, y);
  };
  const auto r = kit::dopri5(counted, 0.0, kit::Arenstorf::initial_state(), 2.0, o);
  CHECK(calls == r.stats.rhs_evals);
  CHECK(calls == 1 + 6 * (r.stats.steps + r.stats.rejected));
}

TEST_CASE("the general embedded driver with the Dormand–Prince tableau takes exactly the production DOPRI5's "
          "steps") {
  for (double tol : {1e-5, 1e-8}) {
    kit::Dopri5Options o;
    o.rtol = o.atol = tol, o.h0 = 1e-4;
    const auto production =
        kit::dopri5(kit::Arenstorf{}, 0.0, kit::Arenstorf::initial_state(), kit::Arenstorf::period, o);
    const auto general = kit::embedded_run(
        tableau_step<kit::Arenstorf, kit::Vec4>, pi_factor, kit::Arenstorf{}, kit::dormand_prince(), 0.0,
        kit::Arenstorf::initial_state(), kit::Arenstorf::period, {tol, tol, 1e-4, 1'000'000});
    CHECK(general.stats.rhs_evals == production.stats.rhs_evals);
    CHECK(general.stats.rejected == production.stats.rejected);
    // Same steps; stage sums rounded in another order, amplified by the orbit: far below tol.
    CHECK((general.accepted.u.back() - production.y).cwiseAbs().maxCoeff() < 0.1 * tol);
  }
}

TEST_CASE("DOPRI5 meets the requested tolerance against the closed forms of free fall and the spring") {
  const kit::FreeFall fall;
  kit::Dopri5Options o;
  const auto falling = kit::dopri5(fall, 0.0, fall.initial_state(), 2.0, o);
  CHECK(falling.y[0] == Approx(fall.position(2.0)).margin(1e-9));  // quadratic: exact up to round-off
  kit::Spring spring;
  spring.damping = 0.5;
  const kit::Vec2 u0(1.5, 0.0);
  for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    o.rtol = o.atol = tol;
    const auto r = kit::dopri5(spring_rhs(spring), 0.0, u0, 3.0, o);
    INFO("tol = " << tol);
    CHECK(std::abs(r.y[0] - kit::spring_motion(spring, u0, 3.0)[0]) <
          30 * tol);  // global error: a few tolerances over ~5 periods
  }
}

TEST_CASE(
    "DOPRI5's dense output follows the exact motion inside each step, to at least fifth order locally") {
  kit::Spring spring;
  const kit::Vec2 u0(1.5, 0.0);
  const auto midpoint_error = [&](double h) {
    kit::Dopri5Options o;
    o.h0 = h, o.h_max = h, o.rtol = o.atol = 1.0;  // force steps of exactly h
    double worst = 0;
    kit::dopri5(
        spring_rhs(spring), 0.0, u0, h, o,
        [&](const kit::Dopri5Dense<2>& dense, const kit::Vec2&, double) {
          const double t = dense.t_old + 0.5 * dense.h;
          worst = std::abs(dense(t)[0] - kit::spring_motion(spring, u0, t)[0]);
        },
        [](double, double) {});
    return worst;
  };
  CHECK(std::log2(midpoint_error(0.02) / midpoint_error(0.01)) >= 4.6);  // 6.0 on this linear problem
  CHECK(midpoint_error(0.01) < 1e-8);
}

TEST_CASE("a NaN from the right-hand side makes DOPRI5 reject and shrink the step, then stop with a clear "
          "message") {
  long nan_calls = 0;
  const auto poisoned = [&](double t, const kit::Vec2& y) {
    if (t > 0.5) ++nan_calls;
    return kit::Vec2(y[1], t > 0.5 ? std::numeric_limits<double>::quiet_NaN() : -y[0]);
  };
  kit::Dopri5Options o;
  const auto r = kit::dopri5(poisoned, 0.0, kit::Vec2(1, 0), 1.0, o);
  CHECK(r.status == kit::RunStatus::step_too_small);
  CHECK_THAT(r.message, ContainsSubstring("NaN or Inf") && ContainsSubstring("rejected"));
  CHECK(r.stats.rejected > 10);  // rejected and shrunk, again and again
  CHECK(r.t <= 0.5 + 1e-12);     // never stepped past the poison
  CHECK(r.y.allFinite());        // never accepted a NaN
}

TEST_CASE(
    "an unreachable tolerance, a collapsing step and an exhausted step budget are reported, not hung on") {
  kit::Dopri5Options o;
  o.rtol = o.atol = 1e-20;
  const auto tight =
      kit::dopri5(kit::Arenstorf{}, 0.0, kit::Arenstorf::initial_state(), kit::Arenstorf::period, o);
  CHECK(tight.status == kit::RunStatus::unreachable);
  CHECK_THAT(tight.message, ContainsSubstring("rtol = 1e-20") && ContainsSubstring("10·ε"));
  CHECK(tight.stats.rhs_evals == 0);
  // y' = y² from y(0) = 1 blows up at t = 1: the step collapses there.
  kit::Dopri5Options blow;
  const auto singular = kit::dopri5([](double, const kit::Vec<1>& y) { return kit::Vec<1>(y[0] * y[0]); },
                                    0.0, kit::Vec<1>(1.0), 2.0, blow);
  CHECK(singular.status == kit::RunStatus::step_too_small);
  CHECK(singular.t == Approx(1.0).margin(1e-3));
  CHECK_THAT(singular.message, ContainsSubstring("step size too small"));
  o.rtol = o.atol = 1e-8;
  o.max_steps = 50;
  const auto short_budget =
      kit::dopri5(kit::Arenstorf{}, 0.0, kit::Arenstorf::initial_state(), kit::Arenstorf::period, o);
  CHECK(short_budget.status == kit::RunStatus::too_many_steps);
  CHECK(short_budget.stats.steps + short_budget.stats.rejected == 50);
}

TEST_CASE("measured by the harness, the kit's DOPRI5 takes Hairer's counts on Arenstorf: 985, 2161 and 5047 "
          "evaluations") {
  const kit::Vec4 y0 = kit::Arenstorf::initial_state();
  const auto curve = kit::measure_work_precision<4>(
      {kit::dopri5_method(kit::Arenstorf{}, 0.0, y0, kit::Arenstorf::period, 1e-4, {1e-6, 1e-8, 1e-10})}, y0,
      {1, 0.0})[0];
  const std::vector<long> evaluations{985, 2161, 5047}, steps{164, 360, 841},
      rejected{23, 21, 0};  // ANCHORS.md
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(curve.points[i].rhs_evals == evaluations[i]);
    CHECK(curve.points[i].attempts() == steps[i]);
    CHECK(curve.points[i].rejected == rejected[i]);
    CHECK(curve.points[i].finished);
  }
  CHECK(curve.points[0].error == Approx(4.4e-2).epsilon(0.02));  // max |y(T) − y0|, Hairer's 4.4e-2
}
