#pragma once
// How kit/problems/spring.hpp's types cross the link (wire.hpp).
#include <tuple>

#include <kit/problems/spring.hpp>

namespace kit {
inline auto fields(Spring& s) { return std::tie(s.mass, s.stiffness, s.damping, s.rest_length); }
}  // namespace kit
