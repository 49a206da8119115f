#pragma once
// The kit's one random source. std::mt19937_64's output sequence is fixed by the C++ standard,
// and the conversion to reals below is the kit's own, so one seed gives the same particles,
// meshes, perturbations and data on every compiler and machine (std::uniform_real_distribution
// is implementation-defined, which is why it is not used).
#include <cstdint>
#include <random>

namespace kit {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [0, 1), 53 random bits.
  double unit() { return double(engine_() >> 11) * 0x1.0p-53; }
  /// Reeves's rand: uniform in [−1, 1).
  double symmetric() { return 2.0 * unit() - 1.0; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace kit
