#pragma once
// Predicted error lines of convergence plots: err = C·Δt^p, a straight line of slope p on
// log-log axes (ERRATA item 2: p = 2 after one step of Euler, p = 1 at a fixed time).
#include <cmath>
#include <vector>

namespace kit {

/// C·x^p at every x of `xs` (same length). For errors against Δt [s], C carries the units that
/// make C·Δt^p an error: Euler at time T on free fall, C = T·|g|/2 [m/s] and p = 1.
inline std::vector<double> power_law(const std::vector<double>& xs, double c, double p = 1.0) {
  std::vector<double> y;
  y.reserve(xs.size());
  for (double x : xs) y.push_back(c * std::pow(x, p));
  return y;
}

}  // namespace kit
