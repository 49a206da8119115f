#include <kit/euler_gap.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <kit/measure.hpp>

namespace kit {

EulerGapCheck check_euler_gaps(const FreeFall& fall, double dt, double t_end,
                               const std::vector<double>& gap_explicit,
                               const std::vector<double>& gap_implicit) {
  if (gap_explicit.size() != gap_implicit.size())
    throw std::invalid_argument("check_euler_gaps: explicit and implicit runs differ in length");
  const double g = std::abs(fall.g);
  const double scale = std::abs(fall.x0) + std::abs(fall.v0) * t_end + g * t_end * t_end + 1.0;  // [m]
  EulerGapCheck check;
  for (std::size_t k = 0; k < gap_explicit.size(); ++k) {
    const double predicted = fall.euler_error(static_cast<long>(k), dt);
    const double e = gap_explicit[k], i = gap_implicit[k];
    check.mismatch = std::max({check.mismatch, std::abs(std::abs(e) - predicted),
                               std::abs(std::abs(i) - predicted)});
    check.predicted.push_back(predicted);
    const bool sizes = agrees(std::abs(e), predicted, 1e-9, 1e-12 * scale) &&
                       agrees(std::abs(i), predicted, 1e-9, 1e-12 * scale);
    // The sides (ERRATA item 3): explicit Euler away from g, implicit Euler toward it.
    check.match.push_back(sizes && e * fall.g <= 0 && i * fall.g >= 0);
  }
  return check;
}

}  // namespace kit
