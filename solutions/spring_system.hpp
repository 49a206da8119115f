#pragma once
// The spring of the lecture ("Masses ressorts") as a first-order system u' = A u + b.
#include <kit/base/not_implemented.hpp>
#include <kit/problems/affine_system.hpp>
#include <kit/problems/spring.hpp>

namespace kit {

/// m x'' = K (L0 − x) − μ x', with u = (x, v):
///   A = [[0, 1], [−K/m, −μ/m]]  [1/s],   b = (0, K L0 / m)  [m/s, m/s²].
inline AffineSystem<2> spring_system(const Spring& spring) {
  AffineSystem<2> s;
  // BEGIN SOLUTION ex 2.1: write x' = v and v' = (K (L0 − x) − μ v)/m as A u + b
  const double k = spring.stiffness / spring.mass, c = spring.damping / spring.mass;
  s.A << 0.0, 1.0, -k, -c;
  s.b << 0.0, k * spring.rest_length;
  // END SOLUTION
  return s;
}

}  // namespace kit
