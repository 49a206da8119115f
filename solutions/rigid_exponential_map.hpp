#pragma once
// The exponential map: over a step with ω [rad/s, world] held constant, R' = ω* R is solved
// exactly by R_{k+1} = exp(h ω*) R_k, and exp of a cross-product matrix is Rodrigues' rotation
// about n = ω/|ω| by θ = h|ω|:
//   exp(θ n*) = I + sin θ n* + (1 − cos θ) n* n*.
// A product of rotations is a rotation: R stays on SO(3) to round-off, at any h.
#include <cmath>

#include <kit/base/not_implemented.hpp>
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// exp(h ω*) R: R turned by h|ω| [rad] about ω's direction; R itself when ω = 0.
inline Mat3 exponential_map_step(const Mat3& R, const Vec3& omega, double h) {
  // BEGIN SOLUTION ex 8.4: Rodrigues' formula with θ = h|ω| and n = ω/|ω|; no division when ω = 0
  const double theta = h * omega.norm();
  if (theta == 0) return R;
  const Vec3 n = omega.normalized();
  Mat3 N;
  N << 0, -n.z(), n.y(), n.z(), 0, -n.x(), -n.y(), n.x(), 0;
  return (Mat3::Identity() + std::sin(theta) * N + (1 - std::cos(theta)) * N * N) * R;
  // END SOLUTION
}

}  // namespace kit
