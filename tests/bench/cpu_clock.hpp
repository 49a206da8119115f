#pragma once
// This thread's CPU time [s], and the machine's load, for the benchmarks. Other work on the
// machine's two cores takes the thread off its core now and then: the wall clock counts those
// pauses, this clock does not (the caches it shares still slow it).
#include <cmath>
#include <cstdlib>
#include <ctime>

namespace kit::bench {

class CpuClock {
 public:
  double seconds() const { return now() - start_; }

 private:
  static double now() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
  }
  double start_ = now();
};

/// The machine's load over the last minute (NaN when unknown): other work on its cores slows
/// every timing, so a benchmark prints it first.
inline double load_average() {
  double load[1] = {NAN};
  return getloadavg(load, 1) == 1 ? load[0] : NAN;
}

}  // namespace kit::bench
