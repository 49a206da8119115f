#include <kit/step_count.hpp>

#include <fmt/format.h>

#include <kit/usage.hpp>

namespace kit {

long require_whole_steps(double t_end, double dt, long max_steps) {
  const long n = whole_steps(t_end, dt);
  if (n >= 1 && n <= max_steps) return n;
  throw UsageError(fmt::format(
      "--t-end {} s with --dt {} s is {:.6g} steps: --t-end must be a whole number of steps of --dt, "
      "from 1 to {} steps (from {} s to {:.6g} s with this --dt)",
      t_end, dt, t_end / dt, max_steps, dt, dt * static_cast<double>(max_steps)));
}

}  // namespace kit
