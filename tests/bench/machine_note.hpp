#pragma once
// The paragraph a CPU-timed benchmark opens with: the memory bandwidth it measured (the bound its
// tables are read against), the cache, the load on the cores, and how its times were taken.
#include <unistd.h>

#include <string>

#include <fmt/format.h>

#include "bandwidth.hpp"
#include "cpu_clock.hpp"

namespace kit_bench {

/// Measures the triad bandwidth [B/s], prints the paragraph, returns the bandwidth.
/// `timing` ends the paragraph's third sentence: "Times below are this thread's CPU time, {timing},".
inline double print_machine_note(const std::string& timing) {
  double stream = 0, array_bytes = 0;
  const double bandwidth = capped_triad_bandwidth(stream, array_bytes);
  fmt::print("Memory bandwidth, one core: {:.1f} GB/s moved by a triad over three arrays of {:.0f} MB "
             "({:.1f} GB/s as\n"
             "STREAM counts it); the last-level cache sysconf reports: {:.0f} MB. Load average at the start: "
             "{:.2f} on\n"
             "{} cores. Times below are this thread's CPU time, {},\n"
             "which other work on the cores does not count, though the caches it shares still slow it.\n\n",
             bandwidth / 1e9, array_bytes / 1e6, stream / 1e9, last_level_cache() / 1e6,
             kit::bench::load_average(), sysconf(_SC_NPROCESSORS_ONLN), timing);
  return bandwidth;
}

}  // namespace kit_bench
