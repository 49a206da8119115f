#pragma once
// Chapter 2's model: a 1-D mass on a spring with viscous damping (lecture, "Masses ressorts"):
//   m x'' = K (L0 − x) − μ x'   ⇔   u' = A u + b,  u = (x, v).
// Building A and b is an exercise (solutions/spring_system.hpp); the closed-form motion and
// the energy, which every chapter compares against, live here.
#include <complex>
#include <utility>

#include <kit/base/state.hpp>

namespace kit {

struct Spring {
  double mass = 1.0;         ///< m [kg]; raising it slows the oscillation (ω = sqrt(K/m))
  double stiffness = 100.0;  ///< K [N/m]; raising it stiffens the system and shrinks Δt limits
  double damping = 0.0;      ///< μ [N·s/m], viscous: force −μ v
  double rest_length = 1.0;  ///< L0 [m], where the spring exerts no force

  /// Undamped angular frequency ω = sqrt(K/m) [rad/s].
  double omega() const;
  /// Damping ratio ζ = μ / (2 sqrt(K m)): 0 undamped, < 1 underdamped, 1 critical, > 1 overdamped.
  double damping_ratio() const;
  /// Kinetic plus elastic energy ½ m v² + ½ K (x − L0)² [J].
  double energy(const Vec2& u) const;
  /// The eigenvalues of A, λ = −ζω ± ω sqrt(ζ² − 1) [1/s] (complex when underdamped).
  std::pair<std::complex<double>, std::complex<double>> eigenvalues() const;
};

/// The exact state at time t [s] from u0 = (x0, v0) at t = 0, for every damping regime
/// (undamped, underdamped, critically damped, overdamped).
Vec2 spring_motion(const Spring& spring, const Vec2& u0, double t);

}  // namespace kit
