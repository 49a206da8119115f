#pragma once
// Random but reproducible parameters for the graded tests (ctest passes --rng-seed).
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include <catch2/catch.hpp>

#include <kit/affine_system.hpp>

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

/// The fall as u' = A u + b: A = [[0, 1], [0, 0]], b = (0, g).
inline kit::AffineSystem<2> affine(const RandomFall& f) {
  kit::AffineSystem<2> s;
  s.A << 0, 1, 0, 0;
  s.b << 0, f.g;
  return s;
}

/// The size of the motion over its steps [m], for absolute tolerances.
inline double scale(const RandomFall& f) {
  const double t = double(f.steps) * f.dt;
  return std::abs(f.x0) + std::abs(f.v0) * t + std::abs(f.g) * t * t + 1.0;
}

/// x after k steps, from the recurrences solved by hand: k(k−1)/2 for explicit Euler,
/// k(k+1)/2 for implicit Euler (lecture, "Par récurrence" and "Résolution implicite").
inline double explicit_euler_x(const RandomFall& f) {
  const double k = double(f.steps);
  return f.x0 + k * f.dt * f.v0 + 0.5 * k * (k - 1) * f.dt * f.dt * f.g;
}
inline double implicit_euler_x(const RandomFall& f) {
  const double k = double(f.steps);
  return f.x0 + k * f.dt * f.v0 + 0.5 * k * (k + 1) * f.dt * f.dt * f.g;
}

/// A random affine system u' = A u + b of size N, entries uniform in [−5, 5].
template <int N>
kit::AffineSystem<N> random_system(std::mt19937_64& rng) {
  kit::AffineSystem<N> s;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) s.A(i, j) = uniform(rng, -5, 5);
    s.b[i] = uniform(rng, -5, 5);
  }
  return s;
}

/// A random state of size N, entries uniform in [−5, 5].
template <int N>
kit::Vec<N> random_state(std::mt19937_64& rng) {
  kit::Vec<N> u;
  for (int i = 0; i < N; ++i) u[i] = uniform(rng, -5, 5);
  return u;
}

/// The parameters, printed with a failing check.
inline std::string describe(const RandomFall& f) {
  std::ostringstream text;
  text << "x0 = " << f.x0 << " m, v0 = " << f.v0 << " m/s, g = " << f.g << " m/s², dt = " << f.dt
       << " s, k = " << f.steps;
  return text.str();
}

}  // namespace kit::test
