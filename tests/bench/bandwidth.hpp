#pragma once
// What the benchmarks share: the fastest of several timings, and this machine's memory bandwidth
// measured by a STREAM-like triad, so that every benchmark states its bound from the same run.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include <kit/base/stopwatch.hpp>

namespace kit_bench {

// Fastest of `samples` timings of `run` [s per call]: a busy machine only ever slows a sample.
template <class Run>
double fastest(Run&& run, int samples = 5, double min_seconds = 0.2) {
  double best = INFINITY;
  for (int i = 0; i < samples; ++i) {
    double seconds = 0;
    kit::time_per_call(
        [&] {
          run();
          return 0;
        },
        seconds, min_seconds);
    best = std::min(best, seconds);
  }
  return best;
}

// Bytes in the last-level cache, from sysconf (0 when unknown).
inline double last_level_cache() {
  return double(std::max({sysconf(_SC_LEVEL3_CACHE_SIZE), sysconf(_SC_LEVEL2_CACHE_SIZE), 0L}));
}

// STREAM's triad, a[i] = b[i] + s·c[i], over arrays of n doubles. Returns the bytes the memory
// moves per second: 32 per element, two reads, one write and the read that brings the written
// line into the cache first (STREAM's own count, 24, leaves that last one out).
inline double triad_bandwidth(std::size_t n, double& stream_convention) {
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  const double s = 3.0;
  const double seconds = fastest(
      [&] {
        double* __restrict pa = a.data();
        const double* __restrict pb = b.data();
        const double* __restrict pc = c.data();
        for (std::size_t i = 0; i < n; ++i) pa[i] = pb[i] + s * pc[i];
      },
      5, 0.0);
  if (a[n / 2] != 7.0) std::abort();  // the loop ran, and was not optimised away
  stream_convention = 24.0 * double(n) / seconds;
  return 32.0 * double(n) / seconds;
}

// The triad with each array at least four times the last-level cache (the STREAM rule), so that
// the arrays come from memory.
inline double triad_bandwidth(double& stream_convention) {
  const std::size_t n = std::max<std::size_t>(std::size_t(1) << 25, std::size_t(4 * last_level_cache() / 8));
  return triad_bandwidth(n, stream_convention);
}

// The same rule with each array at most 2^25 doubles (256 MiB, 768 MiB in all): a virtual
// machine may report its whole socket's L3 (hundreds of MB, of which one core reaches only its
// own slice), and four times that would allocate gigabytes. Arrays of that size still stream
// from memory: together they exceed the whole of such a cache. `array_bytes`: each array's size.
inline double capped_triad_bandwidth(double& stream_convention, double& array_bytes) {
  const std::size_t n = std::clamp<std::size_t>(std::size_t(4 * last_level_cache() / 8), std::size_t(1) << 22,
                                                std::size_t(1) << 25);
  array_bytes = 8.0 * double(n);
  return triad_bandwidth(n, stream_convention);
}

}  // namespace kit_bench
