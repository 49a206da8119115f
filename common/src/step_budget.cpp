#include <kit/step_budget.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include <kit/measure.hpp>

namespace kit {

long StepSweep::fewest_steps() const { return std::max(1L, std::lround(t_end / dt_max)); }

long StepSweep::most_steps() const {
  return std::max(fewest_steps(), std::min(max_steps, std::lround(t_end / dt_min)));
}

std::vector<long> StepSweep::counts(int per_decade) const {
  return geometric_counts(fewest_steps(), most_steps(), per_decade);
}

StepSweep budget_sweep(double t_end, double dt_max, double dt_min, long max_steps) {
  if (!(t_end > 0) || !(dt_min > 0) || !(dt_min <= dt_max) || max_steps < 1)
    throw std::invalid_argument(fmt::format("budget_sweep: needs T > 0, 0 < dt_min <= dt_max and a budget of "
                                            "at least 1 step (T = {}, dt = {} .. {}, budget {})",
                                            t_end, dt_min, dt_max, max_steps));
  return {t_end, dt_max, dt_min, std::max(dt_min, t_end / static_cast<double>(max_steps)), max_steps};
}

}  // namespace kit
