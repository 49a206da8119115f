#include <kit/run_estimate.hpp>

#include <unistd.h>

#include <cmath>

#include <fmt/format.h>

#include <kit/progress.hpp>
#include <kit/usage.hpp>

namespace kit {

namespace {
// Two significant digits without an exponent: "2.1", "30", "120".
std::string amount(double value) {
  return value < 10 ? fmt::format("{:.2g}", value) : fmt::format("{:.0f}", value);
}
}  // namespace

std::string describe_bytes(double bytes) {
  if (!(bytes >= 0) || !std::isfinite(bytes)) return "an unknown amount of memory";
  if (bytes < 1e6) return "under 1 MB";
  if (bytes < 1e9) return fmt::format("{:.0f} MB", bytes / 1e6);
  if (bytes < 1e12) return amount(bytes / 1e9) + " GB";
  if (bytes < 1e15) return amount(bytes / 1e12) + " TB";
  return amount(bytes / 1e15) + " PB";
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
    throw UsageError(fmt::format("{} ({}) takes {}, over the limit of {} and {}: choose values that ask for {}",
                                 what, flags, describe(e), describe_seconds(limits.max_seconds),
                                 describe_bytes(limits.max_bytes), advice));
  }
  const bool announced = e.seconds() >= limits.announce_seconds || e.bytes >= limits.announce_bytes;
  const std::string place = std::string(section) + "/estimate";
  const std::vector<Field> fields{{"steps", e.steps}, {"seconds", e.seconds()}, {"bytes", e.bytes},
                                  {"announced", announced}, {"what", std::string(what)},
                                  {"text", describe(e)}};
  if (announced)
    report.say(place, "\n{what} takes {text}.\n", fields);
  else
    report.store(place, fields);
  ProgressTask::set_total(e.work > 0 ? e.work : e.steps);
}

double machine_memory() {
  return double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
}

}  // namespace kit
