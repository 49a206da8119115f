#pragma once
// How kit/ode/pi_law.hpp's types cross the link (wire.hpp).
#include <tuple>

#include <kit/ode/pi_law.hpp>

namespace kit {
inline auto fields(PiController& c) {
  return std::tie(c.alpha, c.beta, c.safety, c.min_factor, c.max_factor, c.log_previous_error);
}
}  // namespace kit
