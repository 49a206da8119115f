#pragma once
// One step of any explicit embedded Runge–Kutta pair given by its Butcher tableau (the
// lecture's "Avec des ordres différents"): the stages k_i = f(t + c_i h, y + h Σ_j a_ij k_j),
// the solution y + h Σ b_i k_i, and the error estimate h Σ (b_i − b̂_i) k_i, all from the same
// stages: one step, not two (ERRATA item 11).
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include <kit/butcher_tableau.hpp>
#include <kit/not_implemented.hpp>

namespace kit {

template <class State>
struct EmbeddedStep {
  State y;              ///< y_{n+1}, from the weights b
  State error;          ///< h Σ (b_i − b̂_i) k_i, the local error estimate
  State last_stage;     ///< k_s; for an FSAL pair, f(t + h, y_{n+1}), the next step's k_1
  int evaluations = 0;  ///< new evaluations of f (k_1 is given): s − 1
};

/// `k1` = f(t, y) is passed in, so that an FSAL pair reuses its last stage as the next k_1.
/// Shapes: y, k1 and f(t, y) are vectors of one size; t, h in s.
template <class Rhs, class State>
EmbeddedStep<State> embedded_step(const Rhs& f, const ButcherTableau& tableau, double t, const State& y, double h,
                                  const State& k1) {
  EmbeddedStep<State> out;
  // TODO(ex 4.2): compute each stage from the earlier ones (row i of A), then combine them with b and with b − b̂
  throw kit::NotImplemented("ex 4.2", "embedded_rk.hpp");
  return out;
}

}  // namespace kit

#include <kit/adaptive_run.hpp>

#include "pi_controller.hpp"

namespace kit {

struct EmbeddedOptions {
  double rtol = 1e-6, atol = 1e-6;  ///< per component: sk = atol + rtol·max(|y_n|, |y_{n+1}|)
  double h0 = 1e-4;                 ///< first trial step [s]
  long max_steps = 1'000'000;       ///< attempts before too_many_steps
};

/// Drives `embedded_step` over [t0, t_end] with the RMS error norm and the PI controller of
/// ex 4.3 (α = 1/(q+1) − 0.75β for the tableau's embedded order q). The teaching counterpart of
/// the production `dopri5`: any tableau, one heap-allocated stage list per step.
template <class Rhs, class State>
AdaptiveRun<State> embedded_run(const Rhs& f, const ButcherTableau& tableau, double t0, const State& y0, double t_end,
                                const EmbeddedOptions& options) {
  AdaptiveRun<State> run;
  run.accepted.push(t0, y0);
  if (run.message = unreachable_tolerance(options.rtol, options.atol); !run.message.empty()) {
    run.status = RunStatus::unreachable;
    return run;
  }
  PiController control;
  control.alpha = 1.0 / (tableau.embedded_order + 1) - 0.75 * control.beta;
  double t = t0, h = options.h0;
  State y = y0, k1 = f(t0, y0);
  run.stats.rhs_evals = 1;
  bool reject = false;
  while (t < t_end) {
    if (run.stats.steps + run.stats.rejected >= options.max_steps) {
      run.status = RunStatus::too_many_steps;
      run.message = fmt::format("more than {} steps needed; stopped at t = {:.6g}", options.max_steps, t);
      break;
    }
    if (0.1 * h <= std::max(std::abs(t), std::abs(t_end - t0)) * 2.2e-16) {
      run.status = RunStatus::step_too_small;
      run.message = fmt::format("step size too small, h = {:.3g} at t = {:.6g}", h, t);
      break;
    }
    const bool last = t + 1.01 * h > t_end;
    if (last) h = t_end - t;
    const auto step = embedded_step(f, tableau, t, y, h, k1);
    run.stats.rhs_evals += step.evaluations;
    const auto sk = (options.atol + options.rtol * y.array().abs().max(step.y.array().abs())).matrix();
    double err = std::sqrt((step.error.array() / sk.array()).square().sum() / double(y.size()));
    if (!std::isfinite(err)) err = std::numeric_limits<double>::infinity();
    const double factor = pi_step_factor(control, err);
    if (err <= 1.0) {
      remember_accepted(control, err);
      t = last ? t_end : t + h;
      y = step.y;
      k1 = tableau.fsal ? step.last_stage : f(t, y);
      if (!tableau.fsal) ++run.stats.rhs_evals;
      run.accepted.push(t, y);
      run.step_sizes.push_back(h);
      ++run.stats.steps;
      h = reject ? std::min(h * factor, h) : h * factor;
      reject = false;
    } else {
      run.rejected_t.push_back(t);
      run.rejected_h.push_back(h);
      ++run.stats.rejected;
      reject = true;
      h *= factor;
    }
  }
  return run;
}

}  // namespace kit
