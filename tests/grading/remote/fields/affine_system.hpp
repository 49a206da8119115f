#pragma once
// How kit/problems/affine_system.hpp's types cross the link (wire.hpp).
#include <kit/problems/affine_system.hpp>

namespace kit {
template <int N, class Scalar>
auto fields(AffineSystem<N, Scalar>& s) {
  return std::tie(s.A, s.b);
}
}  // namespace kit
