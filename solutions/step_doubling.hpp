#pragma once
// The lecture's automatic step ("Calcul automatique du pas de temps"): compare one step of Δt
// with two steps of Δt/2, e = ‖u1 − u2‖, halve Δt above E_max, double it below E_min:
//
//   Faire  u1 = F(dt, u); u2 = F(dt/2, F(dt/2, u)); e = norm(u1 − u2);
//          si e < E_min: dt *= 2;  si e > E_max: dt /= 2
//   tant que !(E_min < e < E_max)
//
// Taken literally this can loop forever (ERRATA item 10): halving Δt divides e by about
// 2^(p+1), so when E_max/E_min < 2^(p+1) a step can bounce between "too large" and "too small".
// `guarded = false` runs the lecture's loop as written, with a bound on retries that turns the
// endless loop into a reported `trapped` status. `guarded = true` is the repair: accept any
// e ≤ E_max, grow Δt only for the next step, and bound the retries.
#include <cmath>

#include <fmt/format.h>

#include <kit/base/not_implemented.hpp>
#include <kit/ode/adaptive_run.hpp>

namespace kit {

struct StepDoubling {
  double e_min = 1e-8;    ///< below this, double Δt (units of u)
  double e_max = 1e-6;    ///< above this, halve Δt and retry (units of u)
  double dt0 = 1e-3;      ///< first trial step [s]
  double dt_min = 1e-12;  ///< below this the run stops: step_too_small [s]
  int max_retries = 200;  ///< retries of one step before the run reports `trapped`
  long max_steps = 10'000'000;
  bool guarded = true;  ///< false: the lecture's loop exactly as written (plus the retry bound)
};

/// Integrates with `step(t, u, dt) → u_next` (any one-step method) from (t0, u0) to t_end.
/// Every trial costs three steps of the method: one of Δt and two of Δt/2. The run records
/// accepted and rejected steps; the caller counts evaluations (its `step` knows what it costs).
template <class Step, class State>
AdaptiveRun<State> step_doubling(Step&& step, double t0, State u, double t_end, const StepDoubling& options) {
  AdaptiveRun<State> run;
  run.accepted.push(t0, u);
  double t = t0, dt = options.dt0;
  // BEGIN SOLUTION ex 4.1: compare one step of dt with two of dt/2; guarded: accept e <= E_max, grow dt for the next step only; unguarded: loop until E_min < e < E_max
  while (t < t_end && run.status == RunStatus::finished) {
    if (run.stats.steps >= options.max_steps) {
      run.status = RunStatus::too_many_steps;
      run.message = fmt::format("stopped after {} steps at t = {:.6g}", run.stats.steps, t);
      break;
    }
    for (int retry = 0;; ++retry) {
      const double h = std::min(dt, t_end - t);  // the last step lands on t_end
      if (h < options.dt_min) {
        run.status = RunStatus::step_too_small;
        run.message =
            fmt::format("step {:.3g} s fell below dt_min = {:.3g} at t = {:.6g}", h, options.dt_min, t);
        break;
      }
      if (retry >= options.max_retries) {
        run.status = RunStatus::trapped;
        run.message = fmt::format("trapped at t = {:.6g}: {} retries, dt bouncing around {:.3g} between "
                                  "e > E_max and e < E_min (E_max/E_min = {:.3g})",
                                  t, retry, h, options.e_max / options.e_min);
        break;
      }
      const State one = step(t, u, h);
      const State two = step(t + h / 2, step(t, u, h / 2), h / 2);
      const double e = (one - two).norm();
      const bool in_band = options.e_min < e && e < options.e_max;
      // The lecture's loop, plus the one exception it cannot avoid: on the last step dt cannot
      // grow past t_end, so a too-small error there is accepted.
      const bool last = h == t_end - t;
      const bool accept = options.guarded ? e <= options.e_max : in_band || (last && e <= options.e_min);
      if (!std::isfinite(e)) {
        dt = h / 2;
      } else if (accept) {
        t = (h == t_end - t) ? t_end : t + h;
        u = two;  // the two half steps are the more accurate solution
        run.accepted.push(t, u);
        run.step_sizes.push_back(h);
        ++run.stats.steps;
        if (e < options.e_min) dt = 2 * h;  // next step only
        break;
      } else {
        if (e > options.e_max) dt = h / 2;
        if (e < options.e_min) dt = 2 * h;
      }
      run.rejected_t.push_back(t);
      run.rejected_h.push_back(h);
      ++run.stats.rejected;
    }
  }
  // END SOLUTION
  return run;
}

}  // namespace kit
