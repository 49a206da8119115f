#pragma once
// Measurement: convergence-order fits, step sweeps and error norms.
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace kit {

/// Least-squares line through (log10 x_i, log10 y_i). For errors against Δt, `slope` is the
/// observed order p of err ≈ C·Δt^p.
struct LogLogFit {
  double slope = 0.0;
  double intercept = 0.0;  ///< log10 C
};
LogLogFit fit_loglog(std::span<const double> x, std::span<const double> y);

/// Step counts n from `lo` to `hi` spread evenly on a log scale, `per_decade` a decade,
/// ascending and without repeats. Used to sweep Δt = T/n over a whole number of steps.
std::vector<long> geometric_counts(long lo, long hi, int per_decade);

/// Index of the smallest finite value (the first one on ties).
std::size_t argmin(std::span<const double> values);

/// The cost at which a work-precision curve first reaches `target` error: log-log interpolation
/// between the two points that bracket it, taken in order of increasing cost. NaN when the
/// curve never gets that low. `cost` and `error` have one entry per run.
double cost_to_reach(std::span<const double> cost, std::span<const double> error, double target);

/// Errors reached over a range of time steps: one curve of a convergence or round-off plot.
struct Sweep {
  std::vector<double> dt;     ///< time steps [s]
  std::vector<double> error;  ///< |error| reached with each, in the quantity's unit

  void add(double step, double err) {
    dt.push_back(step);
    error.push_back(err);
  }
  /// Observed order: least-squares slope of log error against log Δt, over the points with a
  /// positive error (an exact zero has no logarithm). NaN with fewer than two such points.
  double order() const;
  /// Index of the smallest error: the best Δt before round-off wins.
  std::size_t best() const { return argmin(error); }
  /// {"dt": [...], "error": [...]} for the --json summary.
  nlohmann::json to_json() const { return {{"dt", dt}, {"error", error}}; }
};

/// True when |measured − predicted| is within what round-off can explain:
/// rel·|predicted| + abs. Both bounds are stated by the caller, never hidden.
bool agrees(double measured, double predicted, double rel, double abs);

}  // namespace kit
