#pragma once
// How kit/cloth/cloth_scene.hpp's types cross the link (wire.hpp).
#include <tuple>

#include <kit/cloth/cloth_scene.hpp>

namespace kit {
inline auto fields(SphereCollider& s) { return std::tie(s.center, s.radius, s.friction); }
}  // namespace kit
