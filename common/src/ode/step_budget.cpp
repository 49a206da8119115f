#include <kit/ode/step_budget.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include <kit/base/measure.hpp>

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

RunEstimate roundoff_estimate(const StepSweep& doubles, const StepSweep& floats, const RoundoffCosts& costs) {
  double steps = 0, seconds = 0;
  const std::vector<long> counts = doubles.counts(4);
  // A kernel of cost 0 does not run (its exercise is not written yet): its steps do not count.
  const double per_double = costs.explicit_double > 0 ? 1 : 0;
  const double per_float = (costs.explicit_float > 0 ? 1 : 0) + (costs.implicit_float > 0 ? 1 : 0);
  for (long m : counts) {
    const bool in_float = m <= floats.most_steps();
    steps += static_cast<double>(m) * (per_double + (in_float ? per_float : 0));
    seconds += static_cast<double>(m) *
               (costs.explicit_double + (in_float ? costs.explicit_float + costs.implicit_float : 0.0));
  }
  const double per_step = steps > 0 ? seconds / steps : 0.0;
  const double work = costs.explicit_double > 0 ? seconds / costs.explicit_double : steps;
  return {steps, per_step, 256.0 * static_cast<double>(counts.size()), work};
}

void announce_roundoff(Report& report, const StepSweep& doubles, const StepSweep& floats,
                       const RoundoffCosts& costs) {
  announce_run(report, "roundoff", "The round-off sweep", roundoff_estimate(doubles, floats, costs),
               fmt::format("--t-end {} s, --dt-min {} s", doubles.t_end, doubles.dt_min_requested));
  roundoff_implicit_weight = costs.explicit_double > 0 ? costs.implicit_float / costs.explicit_double : 1.0;
}

}  // namespace kit
