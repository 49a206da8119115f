#pragma once
#include <chrono>

namespace kit {

/// Wall-clock seconds since construction. For the printed cost tables only: tests never
/// compare times (they compare counts).
class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Wall seconds per call of `run`, repeating it until at least `min_total` seconds have
/// passed, so that short runs are not lost in clock resolution. Returns run's last result.
template <class Run>
auto time_per_call(Run&& run, double& seconds_per_call, double min_total = 2e-3) {
  const Stopwatch clock;
  long calls = 0;
  for (;;) {
    auto result = run();
    ++calls;
    if (clock.seconds() >= min_total) {
      seconds_per_call = clock.seconds() / static_cast<double>(calls);
      return result;
    }
  }
}

}  // namespace kit
