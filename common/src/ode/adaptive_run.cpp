#include <kit/ode/adaptive_run.hpp>

#include <limits>

#include <fmt/format.h>

namespace kit {

std::string unreachable_tolerance(double rtol, double atol) {
  const double floor = 10 * std::numeric_limits<double>::epsilon();
  if (rtol >= floor && atol > 0) return {};
  return fmt::format("rtol = {:.3g}, atol = {:.3g}: a tolerance needs rtol >= 10·ε = {:.3g} and atol > 0 in "
                     "double precision",
                     rtol, atol, floor);
}

}  // namespace kit
