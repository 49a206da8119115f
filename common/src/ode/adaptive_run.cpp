#include <kit/ode/adaptive_run.hpp>

#include <limits>

#include <fmt/format.h>

namespace kit {

const char* name(RunStatus status) {
  switch (status) {
    case RunStatus::finished: return "finished";
    case RunStatus::trapped: return "trapped";
    case RunStatus::step_too_small: return "step too small";
    case RunStatus::too_many_steps: return "too many steps";
    case RunStatus::unreachable: return "unreachable tolerance";
  }
  return "?";
}

std::string unreachable_tolerance(double rtol, double atol) {
  const double floor = 10 * std::numeric_limits<double>::epsilon();
  if (rtol >= floor && atol > 0) return {};
  return fmt::format("rtol = {:.3g}, atol = {:.3g}: a tolerance needs rtol >= 10·ε = {:.3g} and atol > 0 in double precision",
                     rtol, atol, floor);
}

}  // namespace kit
