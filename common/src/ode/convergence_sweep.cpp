#include <kit/ode/convergence_sweep.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace kit {

double asymptotic_limit(double omega, double t, int order) {
  return std::min(0.05, std::pow(omega * t, -1.0 / order));
}

SweepHorizon sweep_horizon(double omega, double t_end, long max_steps) {
  const double budget = static_cast<double>(max_steps);
  if (10 * omega * t_end / asymptotic_limit(omega, t_end, 1) <= budget) return {t_end, false};
  // The longest ω·T with 10·ω·T / min(0.05, 1/(ω·T)) = max_steps.
  const double longest = budget >= 4000 ? std::sqrt(budget / 10) : budget / 200;
  return {longest / omega, true};
}

double ConvergenceSweep::best_error() const {
  double best = std::numeric_limits<double>::infinity();
  for (const SweepPoint& p : points) best = std::min(best, p.error);
  return best;
}

ConvergenceSweep fit_sweep(std::vector<SweepPoint> points, double omega, double t, int order) {
  ConvergenceSweep sweep;
  std::vector<double> dt, evaluations, error;
  const double limit = asymptotic_limit(omega, t, order);
  for (const SweepPoint& p : points) {
    if (omega * p.dt <= limit && p.error >= 1e-10 && std::isfinite(p.error)) {
      dt.push_back(p.dt);
      evaluations.push_back(static_cast<double>(p.evaluations));
      error.push_back(p.error);
    }
  }
  sweep.points = std::move(points);
  sweep.fitted = static_cast<long>(dt.size());
  if (sweep.fitted < 2) {  // nothing to fit: the motion dies out, or stays below round-off
    const double nan = std::numeric_limits<double>::quiet_NaN();
    sweep.order = sweep.cost = {nan, nan};
    return sweep;
  }
  sweep.order = fit_loglog(dt, error);
  sweep.cost = fit_loglog(evaluations, error);
  return sweep;
}

EvaluationsNeeded evaluations_needed(const ConvergenceSweep& sweep, int evaluations_per_step,
                                     double tolerance, double max_steps) {
  for (const SweepPoint& p : sweep.points)
    if (p.error <= tolerance) return {static_cast<double>(p.evaluations), false, true};
  const double extrapolated =
      std::pow(10.0, (std::log10(tolerance) - sweep.cost.intercept) / sweep.cost.slope);
  return {extrapolated, true,
          extrapolated / evaluations_per_step <= max_steps};  // NaN when nothing was fitted
}

}  // namespace kit
