#pragma once
// The models of chapter 4 (adaptive Runge–Kutta): the standard non-stiff and stiff test problems
// of Hairer, Nørsett & Wanner, Solving ODEs I, II.0 and II.10 (Arenstorf, Kepler) and II, IV.1
// (Van der Pol). ANCHORS.md lists Hairer's published DOPRI5 counts on Arenstorf.
#include <cmath>

#include <kit/base/state.hpp>

namespace kit {

using Vec4 = Vec<4>;

/// The Arenstorf orbit: a light body in the rotating frame of the Earth–Moon system, a closed
/// orbit of period T. y = (x, y, x', y'), lengths in Earth–Moon distances, time in months / 2π.
struct Arenstorf {
  static constexpr double mu = 0.012277471;  ///< Moon mass fraction
  static constexpr double period = 17.0652165601579625588917206249;
  static Vec4 initial_state() { return {0.994, 0.0, 0.0, -2.00158510637908252240537862224}; }
  Vec4 operator()(double /*t*/, const Vec4& y) const {
    const double mu_earth = 1.0 - mu;
    const double d1 = std::pow((y[0] + mu) * (y[0] + mu) + y[1] * y[1], 1.5);              // to the Earth
    const double d2 = std::pow((y[0] - mu_earth) * (y[0] - mu_earth) + y[1] * y[1], 1.5);  // to the Moon
    return {y[2], y[3], y[0] + 2 * y[3] - mu_earth * (y[0] + mu) / d1 - mu * (y[0] - mu_earth) / d2,
            y[1] - 2 * y[2] - mu_earth * y[1] / d1 - mu * y[1] / d2};
  }
};

/// Kepler's two-body problem with eccentricity e, from pericentre: y = (x, y, x', y'), GM = 1,
/// period 2π. Exact solution by Kepler's equation.
struct Kepler {
  double e = 0.5;  ///< eccentricity in [0, 1)
  Vec4 initial_state() const { return {1.0 - e, 0.0, 0.0, std::sqrt((1.0 + e) / (1.0 - e))}; }
  Vec4 operator()(double /*t*/, const Vec4& y) const {
    const double r3 = std::pow(y[0] * y[0] + y[1] * y[1], 1.5);
    return {y[2], y[3], -y[0] / r3, -y[1] / r3};
  }
  /// The exact state at time t (Newton on Kepler's equation E − e sin E = t).
  Vec4 exact(double t) const {
    double big_e = t;
    for (int i = 0; i < 50; ++i) big_e -= (big_e - e * std::sin(big_e) - t) / (1 - e * std::cos(big_e));
    const double c = std::cos(big_e), s = std::sin(big_e), root = std::sqrt(1 - e * e),
                 rate = 1 / (1 - e * c);
    return {c - e, root * s, -s * rate, root * c * rate};
  }
};

/// Van der Pol's oscillator x'' = μ (1 − x²) x' − x: y = (x, x'). Stiff for large μ, where an
/// explicit method's step is held down by stability, not accuracy.
struct VanDerPol {
  double mu = 10.0;  ///< nonlinear damping
  static Vec2 initial_state() { return {2.0, 0.0}; }
  Vec2 operator()(double /*t*/, const Vec2& y) const { return {y[1], mu * (1 - y[0] * y[0]) * y[1] - y[0]}; }
};

}  // namespace kit
