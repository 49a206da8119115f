#include "euler_gap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <kit/base/measure.hpp>

namespace kit {

EulerGapCheck check_euler_gaps(const FreeFall& fall, double dt, double t_end,
                               const std::vector<double>& gap_explicit,
                               const std::vector<double>& gap_implicit) {
  const bool has_explicit = !gap_explicit.empty(), has_implicit = !gap_implicit.empty();
  if (has_explicit && has_implicit && gap_explicit.size() != gap_implicit.size())
    throw std::invalid_argument("check_euler_gaps: explicit and implicit runs differ in length");
  const double g = std::abs(fall.g);
  const double scale = std::abs(fall.x0) + std::abs(fall.v0) * t_end + g * t_end * t_end + 1.0;  // [m]
  EulerGapCheck check;
  // Samples k = 0..T/Δt: the prediction is made for each, even before either scheme runs.
  const auto samples = std::max({gap_explicit.size(), gap_implicit.size(),
                                 static_cast<std::size_t>(std::max(0L, std::lround(t_end / dt))) + 1});
  for (std::size_t k = 0; k < samples; ++k) {
    const double predicted = fall.euler_error(static_cast<long>(k), dt);
    check.predicted.push_back(predicted);
    // The sides (ERRATA item 3): explicit Euler away from g, implicit Euler toward it.
    const auto fits = [&](double gap, double side) {
      check.mismatch = std::max(check.mismatch, std::abs(std::abs(gap) - predicted));
      return agrees(std::abs(gap), predicted, 1e-9, 1e-12 * scale) && gap * side >= 0;
    };
    const bool e = !has_explicit || fits(gap_explicit[k], -fall.g);
    const bool i = !has_implicit || fits(gap_implicit[k], fall.g);
    if (has_explicit || has_implicit) check.match.push_back(e && i);
  }
  return check;
}

}  // namespace kit
