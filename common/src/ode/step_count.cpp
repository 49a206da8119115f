#include <kit/ode/step_count.hpp>

#include <fmt/format.h>

#include <kit/app/run_estimate.hpp>
#include <kit/base/usage.hpp>

namespace kit {

long require_whole_steps(double t_end, double dt, long max_steps, double bytes_per_step) {
  const long n = whole_steps(t_end, dt);
  if (n >= 1 && n <= max_steps) return n;
  const double asked = t_end / dt, limit = static_cast<double>(max_steps);
  const std::string estimate =
      asked > limit ? fmt::format(" (recording them would take {}; at most {} steps, {}, are recorded)",
                                  describe_bytes(asked * bytes_per_step), max_steps,
                                  describe_bytes(limit * bytes_per_step))
                    : "";
  throw UsageError(fmt::format(
      "--t-end {} s with --dt {} s is {:.6g} steps{}: --t-end must be a whole number of steps of --dt, "
      "from 1 to {} steps (from {} s to {:.6g} s with this --dt)",
      t_end, dt, asked, estimate, max_steps, dt, dt * limit));
}

}  // namespace kit
