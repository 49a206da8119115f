#pragma once
// How kit/affine_system.hpp's types cross the link (wire.hpp).
#include <kit/affine_system.hpp>

namespace kit {
template <int N, class Scalar>
auto fields(AffineSystem<N, Scalar>& s) {
  return std::tie(s.A, s.b);
}
}  // namespace kit
