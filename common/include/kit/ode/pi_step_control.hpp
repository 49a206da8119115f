#pragma once
// The PI law of Hairer's dopri5.f (pi_law.hpp), in a form for the critical path of a DOPRI5 step.
// On a small system a step is bound by latency: the next step's stages cannot start before
// h_new is known, and h_new waits for the error norm and for err^(−α). So:
//   - no sqrt: err² = Σ (e_i/sk_i)² / n is handed over as the sum S = n·err², and
//     err^(−α) = S^(−α/2) · n^(α/2);
//   - no log/exp: S^(−α/2) comes from a FastPower table (relative error ≤ 1e-10);
//   - the memory term safety·n^(α/2)·err_prev^β is computed once per accepted step, off the
//     critical path, and h is folded into it and into the clamp bounds, so that after the
//     power only one multiply, one max and one min remain.
// The step sizes agree with dopri5.f's formula to about 1e-10 relative (tested to 2e-10 in
// tests/common/ode/test_dopri5.cpp), and DOPRI5 keeps dopri5.f's counts on Arenstorf at the three
// published tolerances.
#include <algorithm>
#include <cmath>
#include <limits>

#include <kit/base/fast_power.hpp>
#include <kit/ode/pi_law.hpp>

namespace kit {

class PiStepControl {
 public:
  /// `n` is the number of components in the RMS norm.
  PiStepControl(const PiController& law, int n)
      : law_(law),
        n_(double(n)),
        error_power_(fast_power(-0.5 * law.alpha)),
        previous_power_(fast_power(0.5 * law.beta)),
        reject_scale_(law.safety * std::pow(n_, 0.5 * law.alpha)),
        accept_scale_(reject_scale_ * std::exp(law.beta * law.log_previous_error)) {}

  /// S = Σ (e_i/sk_i)² = n·err². False for NaN, so a poisoned step is never accepted.
  bool acceptable(double sum_of_squares) const { return sum_of_squares <= n_; }

  /// The step after an accepted step of size h: h·clamp(safety·err^(−α)·err_prev^β), at
  /// most h_max, and at most h right after a rejection.
  double after_accepted(double h, double sum_of_squares, double h_max, bool after_rejection) const {
    const double smallest = h * law_.min_factor;
    const double largest = std::min(after_rejection ? h : h * law_.max_factor, h_max);
    return std::min(std::max(error_power_.scaled(sum_of_squares, h * accept_scale_), smallest), largest);
  }

  /// The step after a rejected step of size h: h·clamp(safety·err^(−α), min_factor, 1).
  /// A NaN or Inf error shrinks by the largest factor allowed.
  double after_rejected(double h, double sum_of_squares) const {
    if (!(sum_of_squares < std::numeric_limits<double>::infinity())) return h * law_.min_factor;
    return h * std::clamp(error_power_.scaled(sum_of_squares, reject_scale_), law_.min_factor, 1.0);
  }

  /// Remembers an accepted step's error, floored at 1e-4 as in dopri5.f, for the β term.
  void remember_accepted(double sum_of_squares) {
    const double previous_squared = std::max(sum_of_squares / n_, 1e-8);  // err_prev² ≥ (1e-4)²
    accept_scale_ = previous_power_.scaled(previous_squared, reject_scale_);
  }

 private:
  PiController law_;
  double n_;
  const FastPower& error_power_;     ///< S ↦ S^(−α/2)
  const FastPower& previous_power_;  ///< err_prev² ↦ err_prev^β
  double reject_scale_;              ///< safety · n^(α/2)
  double accept_scale_;              ///< safety · n^(α/2) · err_prev^β
};

}  // namespace kit
