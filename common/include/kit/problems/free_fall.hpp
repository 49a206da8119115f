#pragma once
// Chapter 1's model: a particle of mass m in free fall, m a = m g (lecture, "Chute libre").
#include <cmath>
#include <kit/problems/affine_system.hpp>

namespace kit {

/// Free fall along one vertical axis. Sign convention: the axis points up, so g < 0 pulls
/// down and a larger x is higher. The mass cancels out of x'' = g and is not a parameter.
struct FreeFall {
  double x0 = 20.0;  ///< initial height x(0) [m]
  double v0 = 0.0;   ///< initial velocity v(0) [m/s], positive = upward
  double g = -9.81;  ///< gravitational acceleration [m/s²], negative = downward

  /// u(0) = (x0, v0).
  Vec2 initial_state() const { return {x0, v0}; }

  /// u' = A u + b with A = [[0, 1], [0, 0]] and b = (0, g).
  AffineSystem<2> affine() const {
    AffineSystem<2> s;
    s.A << 0.0, 1.0, 0.0, 0.0;
    s.b << 0.0, g;
    return s;
  }

  /// f(t, u) = (v, g), the right-hand side the lecture's loop evaluates.
  Vec2 operator()(double /*t*/, const Vec2& u) const { return {u[1], g}; }

  /// Exact position x̃(t) = x0 + v0 t + g t²/2 [m].
  double position(double t) const { return x0 + v0 * t + 0.5 * g * t * t; }
  /// Exact velocity ṽ(t) = v0 + g t [m/s].
  double velocity(double t) const { return v0 + g * t; }
  Vec2 exact_state(double t) const { return {position(t), velocity(t)}; }

  /// Position after k explicit Euler steps of Δt: x0 + kΔt v0 + k(k−1)/2 Δt² g
  /// (lecture, "Par récurrence").
  double explicit_euler_position(long k, double dt) const {
    const double kd = static_cast<double>(k);
    return x0 + kd * dt * v0 + 0.5 * kd * (kd - 1.0) * dt * dt * g;
  }
  /// Position after k implicit Euler steps of Δt: x0 + kΔt v0 + k(k+1)/2 Δt² g.
  double implicit_euler_position(long k, double dt) const {
    const double kd = static_cast<double>(k);
    return x0 + kd * dt * v0 + 0.5 * kd * (kd + 1.0) * dt * dt * g;
  }
  /// |x_k − x̃(kΔt)| of either Euler after k steps: k/2 · Δt² · |g| [m]. The lecture drops
  /// the |g| (ERRATA item 1). Explicit Euler is off by +k/2 Δt² |g| (above the parabola for
  /// g < 0), implicit Euler by the same amount below.
  double euler_error(long k, double dt) const { return 0.5 * static_cast<double>(k) * dt * dt * std::abs(g); }
};

}  // namespace kit
