#pragma once
// The general adaptive driver for any embedded pair given by its Butcher tableau: the teaching
// counterpart of the production kit::dopri5. It takes the one-step method and the step-size law
// as arguments, so that chapter 4 can run a student's ex 4.2 and ex 4.3 through it, while the
// kit itself includes no student file.
//   step(f, tableau, t, y, h, k1) → EmbeddedStep<State>      (ex 4.2's kit::embedded_step)
//   factor(const PiController&, err) → h_new / h              (ex 4.3's kit::pi_step_factor)
// Error norm: RMS of e_i / sk_i with sk_i = atol + rtol·max(|y_n,i|, |y_{n+1},i|), as dopri5.f.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include <kit/ode/adaptive_run.hpp>
#include <kit/ode/butcher_tableau.hpp>
#include <kit/ode/embedded_step.hpp>
#include <kit/ode/pi_law.hpp>

namespace kit {

struct EmbeddedOptions {
  double rtol = 1e-6, atol = 1e-6;  ///< per component: sk = atol + rtol·max(|y_n|, |y_{n+1}|)
  double h0 = 1e-4;                 ///< first trial step [s]
  long max_steps = 1'000'000;       ///< attempts before too_many_steps
};

template <class Step, class Factor, class Rhs, class State>
AdaptiveRun<State> embedded_run(Step&& step, Factor&& factor, const Rhs& f, const ButcherTableau& tableau,
                                double t0, const State& y0, double t_end, const EmbeddedOptions& options) {
  AdaptiveRun<State> run;
  run.accepted.push(t0, y0);
  if (run.message = unreachable_tolerance(options.rtol, options.atol); !run.message.empty()) {
    run.status = RunStatus::unreachable;
    return run;
  }
  PiController control = pi_controller_for_order(tableau.embedded_order);
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
    if (0.1 * h <= std::max(std::abs(t), std::abs(t_end - t0)) * std::numeric_limits<double>::epsilon()) {
      run.status = RunStatus::step_too_small;
      run.message = fmt::format("step size too small, h = {:.3g} at t = {:.6g}", h, t);
      break;
    }
    const bool last = t + 1.01 * h > t_end;
    if (last) h = t_end - t;
    const EmbeddedStep<State> attempt = step(f, tableau, t, y, h, k1);
    run.stats.rhs_evals += attempt.evaluations;
    const auto sk = (options.atol + options.rtol * y.array().abs().max(attempt.y.array().abs())).matrix();
    double err = std::sqrt((attempt.error.array() / sk.array()).square().sum() / double(y.size()));
    if (!std::isfinite(err)) err = std::numeric_limits<double>::infinity();
    const double h_factor = factor(std::as_const(control), err);
    if (err <= 1.0) {
      remember_accepted(control, err);
      t = last ? t_end : t + h;
      y = attempt.y;
      k1 = tableau.fsal ? attempt.last_stage : f(t, y);
      if (!tableau.fsal) ++run.stats.rhs_evals;
      run.accepted.push(t, y);
      run.step_sizes.push_back(h);
      ++run.stats.steps;
      h = reject ? std::min(h * h_factor, h) : h * h_factor;
      reject = false;
    } else {
      run.rejected_t.push_back(t);
      run.rejected_h.push_back(h);
      ++run.stats.rejected;
      reject = true;
      h *= h_factor;
    }
  }
  return run;
}

}  // namespace kit
