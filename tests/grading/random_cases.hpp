#pragma once
// Random but reproducible parameters for the graded tests (ctest passes --rng-seed).
#include <random>

#include <catch2/catch.hpp>

namespace kit::test {

/// A generator seeded from Catch's --rng-seed, so a failing case can be replayed.
inline std::mt19937_64 random_engine() { return std::mt19937_64(Catch::rngSeed()); }

inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

/// A random fall: x0 in [−50, 50] m, v0 in [−20, 20] m/s, |g| in [1, 30] m/s² of either sign.
struct RandomFall {
  double x0, v0, g, dt;
  long steps;
};
inline RandomFall random_fall(std::mt19937_64& rng) {
  RandomFall f{};
  f.x0 = uniform(rng, -50, 50);
  f.v0 = uniform(rng, -20, 20);
  f.g = uniform(rng, 1, 30) * (uniform(rng, 0, 1) < 0.5 ? -1.0 : 1.0);
  f.dt = uniform(rng, 1e-3, 0.2);
  f.steps = std::uniform_int_distribution<long>(1, 400)(rng);
  return f;
}

}  // namespace kit::test
