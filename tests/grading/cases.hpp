#pragma once
// Cases shared by the graded tests: random but reproducible parameters (ctest passes
// --rng-seed), closed forms computed independently of the kit, and convergence checks.
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include <kit_catch.hpp>

#include <kit/problems/affine_system.hpp>
#include <kit/problems/spring.hpp>

namespace kit::test {

/// A generator seeded from Catch's --rng-seed, so a failing case can be replayed.
inline std::mt19937_64 random_engine() { return std::mt19937_64(kit::testing::seed()); }

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

/// A random spring: m in [0.1, 10] kg, K in [1, 1000] N/m, L0 in [−2, 2] m, and a damping
/// ratio ζ in [0, 3] (every regime: under-, critically and overdamped).
inline kit::Spring random_spring(std::mt19937_64& rng) {
  kit::Spring s;
  s.mass = uniform(rng, 0.1, 10);
  s.stiffness = uniform(rng, 1, 1000);
  s.rest_length = uniform(rng, -2, 2);
  const double zeta = uniform(rng, 0, 1) < 0.1 ? 1.0 : uniform(rng, 0, 3);
  s.damping = 2 * zeta * std::sqrt(s.stiffness * s.mass);
  return s;
}

inline std::string describe(const kit::Spring& s) {
  std::ostringstream text;
  text << "m = " << s.mass << " kg, K = " << s.stiffness << " N/m, mu = " << s.damping
       << " N·s/m, L0 = " << s.rest_length << " m (zeta = " << s.damping_ratio() << ")";
  return text.str();
}

/// The parameters, printed with a failing check.
inline std::string describe(const RandomFall& f) {
  std::ostringstream text;
  text << "x0 = " << f.x0 << " m, v0 = " << f.v0 << " m/s, g = " << f.g << " m/s², dt = " << f.dt
       << " s, k = " << f.steps;
  return text.str();
}

/// The observed order log2(error(n) / error(2n)) of a method whose error after n steps is error(n).
template <class ErrorOf>
double observed_order(ErrorOf&& error, long n) {
  return std::log2(error(n) / error(2 * n));
}

/// |x_n − x(1 s)| after n steps of `step(f, t, u, dt)` on a damped spring (m = 1 kg,
/// K = 100 N/m, μ = 1 N·s/m, L0 = 1 m) from (1.5 m, 0), its A and b written out here.
template <class Step>
double damped_spring_error(Step&& step, long n) {
  kit::Spring spring;
  spring.damping = 1.0;
  kit::AffineSystem<2> s;
  s.A << 0, 1, -100, -1;
  s.b << 0, 100;
  const kit::Vec2 u0(1.5, 0.0);
  kit::Vec2 u = u0;
  for (long k = 0; k < n; ++k) u = step(s, double(k) / double(n), u, 1.0 / double(n));
  return std::abs(u[0] - kit::spring_motion(spring, u0, 1.0)[0]);
}

}  // namespace kit::test
