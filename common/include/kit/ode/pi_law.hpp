#pragma once
// The parameters and the memory of a PI step-size controller (Gustafsson; Hairer's dopri5.f):
//   h_new = h · clamp( safety · err^(−α) · err_prev^β ,  min_factor, max_factor ),
//   α = 1/(q+1) − 0.75 β,  q the embedded order (4 for DOPRI5, so α = 0.17 with β = 0.04).
// err is the error norm divided by the tolerance: a step is accepted when err ≤ 1.
// Plain data: the student's law (ex 4.3, pi_controller.hpp) and the kit's production control
// (pi_step_control.hpp) both read it.
#include <algorithm>
#include <cmath>

namespace kit {

struct PiController {
  double alpha = 0.2 - 0.75 * 0.04;  ///< exponent of the current error; raising it reacts faster
  double beta = 0.04;                ///< exponent of the previous accepted error (0: plain I control)
  double safety = 0.9;               ///< aim below the tolerance, not at it
  double min_factor = 0.2;           ///< never shrink h by more than 5× at once
  double max_factor = 10.0;          ///< never grow h by more than 10× at once
  /// log of the previous accepted error, floored at 1e-4 as in dopri5.f; starts at log(1e-4).
  double log_previous_error = std::log(1e-4);
};

/// α for an embedded pair of order q, keeping β: α = 1/(q+1) − 0.75 β.
inline PiController pi_controller_for_order(int embedded_order, PiController law = {}) {
  law.alpha = 1.0 / (embedded_order + 1) - 0.75 * law.beta;
  return law;
}

/// Remembers an accepted step's error for the next factor (floored at 1e-4, as in dopri5.f).
inline void remember_accepted(PiController& c, double err) {
  c.log_previous_error = std::log(std::max(err, 1e-4));
}

}  // namespace kit
