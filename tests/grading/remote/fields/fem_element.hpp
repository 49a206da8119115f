#pragma once
// How kit/fem/fem_element.hpp's and kit/fem/fem_material.hpp's types cross the link (wire.hpp).
#include <tuple>

#include <kit/fem/fem_element.hpp>

namespace kit {
inline auto fields(Lame& l) { return std::tie(l.lambda, l.mu); }
}  // namespace kit
