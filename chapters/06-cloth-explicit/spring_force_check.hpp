#pragma once
// What chapter 6 checks of a spring force (ex 6.1) before a cloth is built on it: Newton's third
// law, the force as minus the gradient of the spring energy ½K(l − L0)², and damping that only
// resists changes of length.
#include <kit/cloth/cloth_system.hpp>

namespace kit {

struct SpringForceCheck {
  int springs = 0;             ///< random springs tried
  double third_law = 0;        ///< max |F_a(a, b) + F_b(b, a)| / |F_a| (0: equal and opposite)
  double energy_gradient = 0;  ///< max |F_a + ∇_a E| / |F_a|, ∇ by central differences (undamped)
  double rigid_damping = 0;    ///< max |F_a(moving together) − F_a(at rest)| / (μ |v|) (0: not slowed)
  double stretch_damping = 0;  ///< max relative error of the damping of a pure stretch rate, μ·rate
};

/// Tries `force` on `springs` random springs (lengths 0.5–2 times their rest length, K in
/// 1–1e4 N/m, μ in 0–10 N·s/m, velocities up to 5 m/s), from a fixed seed.
SpringForceCheck check_spring_force(SpringForce force, int springs = 1000);

}  // namespace kit
