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
  // TODO(ex 4.1): compare one step of dt with two of dt/2; guarded: accept e <= E_max, grow dt for the next step only; unguarded: loop until E_min < e < E_max
  throw kit::NotImplemented("ex 4.1", "step_doubling.hpp");
  return run;
}

}  // namespace kit
