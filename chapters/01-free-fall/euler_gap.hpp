#pragma once
// ERRATA item 1, checked on actual runs: after k steps of Δt on free fall, explicit Euler misses
// the exact parabola by k/2·Δt²·|g| on the side away from g (above it when g < 0), and implicit
// Euler by the same amount on g's side (ERRATA item 3). The lecture drops the |g|.
#include <optional>
#include <vector>

#include <kit/problems/free_fall.hpp>

namespace kit {

/// How runs of both Euler schemes compare with that prediction, sample by sample.
struct EulerGapCheck {
  std::vector<double> predicted;  ///< k/2·Δt²·|g| [m] at each sample k
  std::vector<bool> match;        ///< every gap given equals it to round-off, each on its own side
                                  ///< (empty when neither scheme was given)
  double mismatch = 0;            ///< max over k and the schemes given of | |gap_k| − predicted_k | [m]
  /// The mismatch, or none when neither scheme was given.
  std::optional<double> checked_mismatch() const {
    return match.empty() ? std::nullopt : std::optional<double>(mismatch);
  }
};

/// Checks the gaps x_k − x̃(kΔt) [m] of explicit and implicit Euler (sample k at t = kΔt,
/// dt = Δt [s]) over [0, t_end] against the prediction. Either may be empty (a scheme not
/// written yet): the other is checked alone; when both are given they have the same length.
/// The prediction covers k = 0..T/Δt whatever is given. "To round-off" means within
/// 1e-9 relative plus 1e-12 of the motion's scale |x0| + |v0|·T + |g|·T² + 1 m.
EulerGapCheck check_euler_gaps(const FreeFall& fall, double dt, double t_end,
                               const std::vector<double>& gap_explicit,
                               const std::vector<double>& gap_implicit);

}  // namespace kit
