#pragma once
// How kit/cloth/cloth_implicit_kernels.hpp's types cross the link (wire.hpp). ImplicitSystemInput
// holds references, so its stub and harness send its members one by one.
#include <tuple>

#include <kit/cloth/cloth_implicit_kernels.hpp>

#include "cloth.hpp"

namespace kit {
inline auto fields(PcgResult& p) {
  return std::tie(p.x, p.iterations, p.residual, p.converged, p.negative_curvature);
}
}  // namespace kit
