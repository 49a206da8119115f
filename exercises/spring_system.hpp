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
  // TODO(ex 2.1): write x' = v and v' = (K (L0 − x) − μ v)/m as A u + b
  throw kit::NotImplemented("ex 2.1", "spring_system.hpp");
  return s;
}

}  // namespace kit
