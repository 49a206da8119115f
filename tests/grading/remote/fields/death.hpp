#pragma once
// How kit/sprites/particle_update.hpp's Death crosses the link (wire.hpp).
#include <tuple>

#include <kit/sprites/particle_update.hpp>

#include "sprites.hpp"

namespace kit {
inline auto fields(Death& d) { return std::tie(d.x, d.y, d.z, d.vx, d.vy, d.vz, d.emitter); }
}  // namespace kit
