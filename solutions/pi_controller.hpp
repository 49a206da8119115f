#pragma once
// Step-size control with memory (Gustafsson's PI controller, as in Hairer's dopri5.f):
//   h_new = h · clamp( safety · err^(−α) · err_prev^β ,  min_factor, max_factor ),
//   α = 1/(q+1) − 0.75 β,  q the embedded order (4 for DOPRI5, so α = 0.17 with β = 0.04).
// err is the error norm divided by the tolerance: a step is accepted when err ≤ 1. The β term
// remembers the previous accepted step and damps the oscillation of a pure err^(−1/(q+1)) rule.
#include <algorithm>
#include <cmath>

#include <kit/not_implemented.hpp>

namespace kit {

struct PiController {
  double alpha = 0.2 - 0.75 * 0.04;  ///< exponent of the current error
  double beta = 0.04;                ///< exponent of the previous accepted error (0: plain I control)
  double safety = 0.9;               ///< aim below the tolerance, not at it
  double min_factor = 0.2;           ///< never shrink h by more than 5× at once
  double max_factor = 10.0;          ///< never grow h by more than 10× at once
  /// log of the previous accepted error, floored at 1e-4 as in dopri5.f; starts at log(1e-4).
  double log_previous_error = std::log(1e-4);
};

/// h_new / h after an attempt with error `err` (0 < err, err = 1 at the tolerance).
/// On acceptance (err ≤ 1) the factor uses both errors; on rejection only the current one,
/// and it never exceeds 1. One log and one exp per call: no pow.
inline double pi_step_factor(const PiController& c, double err) {
  // BEGIN SOLUTION ex 4.3: factor = safety·err^(−α)·prev^β, clamped to [min, max]; on rejection use err^(−α)·safety alone, at most 1
  const double log_err = std::log(std::max(err, 1e-300));
  if (err <= 1.0) {
    const double factor = c.safety * std::exp(-c.alpha * log_err + c.beta * c.log_previous_error);
    return std::clamp(factor, c.min_factor, c.max_factor);
  }
  return std::clamp(c.safety * std::exp(-c.alpha * log_err), c.min_factor, 1.0);
  // END SOLUTION
}

/// Remembers an accepted step's error for the next factor.
inline void remember_accepted(PiController& c, double err) { c.log_previous_error = std::log(std::max(err, 1e-4)); }

}  // namespace kit
