#include <kit/app/run_estimate.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include <kit/app/progress.hpp>
#include <kit/base/usage.hpp>

namespace kit {

std::string describe_bytes(double bytes) {
  if (!(bytes >= 0) || !std::isfinite(bytes)) return "an unknown amount of memory";
  if (bytes < 1e6) return "under 1 MB";
  // No exponent: two significant digits below 10 ("2.1 GB"), whole numbers above ("125 GB"). The
  // unit is chosen after rounding, so that 999.7 GB reads "1 TB", not "1000 GB".
  const char* units[] = {"MB", "GB", "TB", "PB"};
  double value = bytes / 1e6;
  int unit = 0;
  for (;;) {
    const std::string text = value < 9.95 ? fmt::format("{:.2g}", value) : fmt::format("{:.0f}", value);
    if (std::stod(text) < 1000 || unit == 3) return text + " " + units[unit];
    value /= 1000;
    ++unit;
  }
}

std::string describe(const RunEstimate& e) {
  return fmt::format("about {:.2g} {}: {} and {}", e.steps, e.unit, about_seconds(e.seconds()),
                     describe_bytes(e.bytes));
}

bool over_limits(const RunEstimate& e, const RunLimits& limits) {
  return !(e.seconds() <= limits.max_seconds) || !(e.bytes <= limits.max_bytes);
}

void announce_run(Report& report, std::string_view section, std::string_view what, const RunEstimate& e,
                  std::string_view flags, const RunLimits& limits) {
  if (over_limits(e, limits)) {
    // The advice names what is over: the time (fewer steps), the memory, or both.
    const bool too_long = !(e.seconds() <= limits.max_seconds), too_large = !(e.bytes <= limits.max_bytes);
    const std::string advice = too_long && too_large ? fmt::format("fewer {} and less memory", e.unit)
                               : too_long            ? fmt::format("fewer {}", e.unit)
                                                     : "less memory";
    throw UsageError(fmt::format(
        "{} ({}) takes {}, over the limit of {} and {}: choose values that ask for {}", what, flags,
        describe(e), describe_seconds(limits.max_seconds), describe_bytes(limits.max_bytes), advice));
  }
  const bool announced = e.seconds() >= limits.announce_seconds || e.bytes >= limits.announce_bytes;
  const std::string place = std::string(section) + "/estimate";
  const std::vector<Field> fields{{"steps", e.steps},          {"seconds", e.seconds()},
                                  {"bytes", e.bytes},          {"announced", announced},
                                  {"what", std::string(what)}, {"text", describe(e)}};
  if (announced)
    report.say(place, "\n{what} takes {text}.\n", fields);
  else
    report.store(place, fields);
  ProgressTask::set_total(e.work > 0 ? e.work : e.steps);
}

double machine_memory() {
  const double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
  const char* text = std::getenv("KIT_MEMORY_LIMIT");
  if (!text || !*text) return physical;
  char* end = nullptr;
  const double limit = std::strtod(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(limit) || !(limit >= 1e6))
    throw UsageError(
        fmt::format("KIT_MEMORY_LIMIT '{}': expected a number of bytes in [1e6, inf), such as 8e9", text));
  return std::min(physical, limit);  // it lowers the bound, never raises it
}

}  // namespace kit
