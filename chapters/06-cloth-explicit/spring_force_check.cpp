// Checks of a spring force (spring_force_check.hpp).
#include "spring_force_check.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace kit {

SpringForceCheck check_spring_force(SpringForce force, int springs) {
  std::mt19937_64 random(61);
  std::uniform_real_distribution<double> unit(-1, 1), ratio(0.5, 2), log_k(0, 4), mu(0, 10);
  const auto vector = [&](double scale) {
    return Vec3(scale * unit(random), scale * unit(random), scale * unit(random));
  };
  SpringForceCheck check;
  check.springs = springs;
  for (int s = 0; s < springs; ++s) {
    const Vec3 xa = vector(1), offset = vector(1).normalized(), va = vector(5), vb = vector(5);
    const double rest = 0.1 + std::abs(unit(random));
    const Vec3 xb = xa + ratio(random) * rest * offset;
    const SpringFamily family{std::pow(10.0, log_k(random)), mu(random)};
    const Vec3 fa = force(xa, xb, va, vb, rest, family), fb = force(xb, xa, vb, va, rest, family);
    const double size = std::max(fa.norm(), 1e-300);
    check.third_law = std::max(check.third_law, (fa + fb).norm() / size);
    // Undamped: F_a = −∂E/∂x_a, E = ½K(|x_a − x_b| − L0)², by central differences (error ~h²).
    const SpringFamily stiff{family.stiffness, 0};
    const Vec3 zero = Vec3::Zero(), f = force(xa, xb, zero, zero, rest, stiff);
    const auto energy = [&](const Vec3& p) {
      const double e = (p - xb).norm() - rest;
      return 0.5 * stiff.stiffness * e * e;
    };
    Vec3 gradient;
    const double h = 1e-6 * rest;
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 step = Vec3::Zero();
      step[axis] = h;
      gradient[axis] = (energy(xa + step) - energy(xa - step)) / (2 * h);
    }
    check.energy_gradient =
        std::max(check.energy_gradient, (f + gradient).norm() / std::max(f.norm(), 1e-300));
    // Both ends moving with the same velocity: the length does not change, so no damping.
    const Vec3 together = force(xa, xb, va, va, rest, family) - force(xa, xb, zero, zero, rest, family);
    if (family.damping > 0)
      check.rigid_damping = std::max(check.rigid_damping, together.norm() / (family.damping * va.norm()));
    // a moving away from b along the spring at speed w: the damping force is −μ w along x̂.
    const Vec3 along = (xa - xb).normalized();
    const double w = 1 + std::abs(unit(random));
    const Vec3 damping =
        force(xa, xb, w * along, zero, rest, family) - force(xa, xb, zero, zero, rest, family);
    if (family.damping > 0)
      check.stretch_damping = std::max(check.stretch_damping,
                                       (damping + family.damping * w * along).norm() / (family.damping * w));
  }
  return check;
}

}  // namespace kit
