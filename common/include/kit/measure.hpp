#pragma once
// Measurement: convergence-order fits, step sweeps and error norms.
#include <span>
#include <vector>

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

/// True when |measured − predicted| is within what round-off can explain:
/// rel·|predicted| + abs. Both bounds are stated by the caller, never hidden.
bool agrees(double measured, double predicted, double rel, double abs);

}  // namespace kit
