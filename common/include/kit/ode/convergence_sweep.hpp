#pragma once
// A fixed-step scheme's error at a time T over a sweep of step counts, the order and cost fits
// read from it, and what a target error then costs (chapter 3, "what order buys"):
//   error_at(n) = |x_n − x(T)| after n steps of Δt = T/n
//     → ConvergenceSweep (points, order fit, cost fit) → evaluations_needed(tolerance).
// On an oscillator of angular frequency ω the fit keeps the asymptotic range (asymptotic_limit)
// and errors above round-off, ≥ 1e-10 (in the quantity's unit).
#include <algorithm>
#include <cmath>
#include <vector>

#include <kit/base/measure.hpp>

namespace kit {

/// One run of a sweep.
struct SweepPoint {
  double dt = 0;         ///< Δt = T/n [s]
  double error = 0;      ///< |x_n − x(T)|, units of x
  long evaluations = 0;  ///< right-hand-side evaluations over [0, T]: n × evaluations per step
};

/// The largest ω·Δt of the asymptotic range of a scheme of order p at horizon T: 0.05, and less
/// on long horizons, where the global error grows like ω·T·(ω·Δt)^p, which must stay below 1:
/// min(0.05, (ω·T)^(−1/p)). For p = 1 both bounds meet at ω·T = 20 (chapter 3's default spring).
double asymptotic_limit(double omega, double t, int order);

/// Where a sweep measures. The fit of a first-order scheme needs a decade of Δt below its
/// asymptotic_limit, hence n ≥ 10·ω·T / asymptotic_limit steps: at most `max_steps` when
/// ω·T ≤ sqrt(max_steps/10) (316 for 10⁶ steps). A longer T would make the sweep unaffordable or
/// its fit meaningless, so the errors are measured at the longest T that allows instead: a valid
/// --t-end is never refused.
struct SweepHorizon {
  double t = 0;          ///< T at which errors are measured [s]
  bool adapted = false;  ///< true when t is shorter than the T asked for
};
SweepHorizon sweep_horizon(double omega, double t_end, long max_steps = 1'000'000);

/// A scheme's sweep and the two fits chapter 3 reads.
struct ConvergenceSweep {
  std::vector<SweepPoint> points;  ///< by ascending n (descending Δt)
  LogLogFit order;                 ///< error against Δt over the fitted points: slope = observed order
  LogLogFit cost;                  ///< error against evaluations over the same points
  long fitted = 0;                 ///< finite points in the asymptotic range and above round-off;
                                   ///< below 2, both fits are NaN (a motion that dies out too fast)
  /// The smallest finite error of the sweep (where round-off or the sweep's end stops it).
  double best_error() const;
};

/// The fits of `points` of a scheme of order `order`, measured at horizon `t` [s] on an
/// oscillator of angular frequency `omega` [rad/s].
ConvergenceSweep fit_sweep(std::vector<SweepPoint> points, double omega, double t, int order);

/// Errors at horizon T for n = max(10, ⌈ω·T/2⌉) … max_steps steps, 8 counts a decade, of a
/// scheme of order `order`: error_at(n) → |x_n − x(T)|.
template <class ErrorAt>
ConvergenceSweep sweep_convergence(ErrorAt&& error_at, double t, double omega, int order,
                                   int evaluations_per_step, long max_steps = 1'000'000) {
  std::vector<SweepPoint> points;
  for (long n : geometric_counts(std::max(10L, static_cast<long>(std::ceil(omega * t / 2))), max_steps, 8))
    points.push_back({t / static_cast<double>(n), error_at(n), n * evaluations_per_step});
  return fit_sweep(std::move(points), omega, t, order);
}

/// What reaching an error costs.
struct EvaluationsNeeded {
  double evaluations = 0;     ///< right-hand-side evaluations over [0, T]
  bool extrapolated = false;  ///< false: a measured point; true: the cost fit extended past the sweep
  bool reachable = true;      ///< false: more than `max_steps` steps, where round-off wins first
};

/// The first measured point at or below `tolerance` or, when none is, the extrapolation of the
/// cost fit. Past 10⁹ steps it is "never": chapter 1 measured round-off overtaking truncation
/// there in double precision.
EvaluationsNeeded evaluations_needed(const ConvergenceSweep& sweep, int evaluations_per_step,
                                     double tolerance, double max_steps = 1e9);

}  // namespace kit
