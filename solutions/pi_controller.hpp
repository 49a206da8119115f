#pragma once
// Step-size control with memory (Gustafsson's PI controller, as in Hairer's dopri5.f):
//   h_new = h · clamp( safety · err^(−α) · err_prev^β ,  min_factor, max_factor ),
//   α = 1/(q+1) − 0.75 β,  q the embedded order (4 for DOPRI5, so α = 0.17 with β = 0.04).
// err is the error norm divided by the tolerance: a step is accepted when err ≤ 1. The β term
// remembers the previous accepted step and damps the oscillation of a pure err^(−1/(q+1)) rule.
// The parameters and the memory (kit::PiController, kit::remember_accepted) are in pi_law.hpp.
#include <algorithm>
#include <cmath>

#include <kit/base/not_implemented.hpp>
#include <kit/ode/pi_law.hpp>

namespace kit {

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

}  // namespace kit
