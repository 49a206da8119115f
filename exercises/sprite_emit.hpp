#pragma once
// Ex 5.1: one new particle of an emitter (Reeves 1983, §2.2). Every attribute is drawn as
//   mean + rand·variance,  rand uniform in [−1, 1)   (random.symmetric(), or kit::draw),
// its position and direction by the emitter's shape (the geometry is in kit/sprites/emitter.hpp).
#include <algorithm>
#include <cstdint>

#include <kit/base/not_implemented.hpp>
#include <kit/base/random.hpp>
#include <kit/sprites/emitter.hpp>
#include <kit/sprites/particles.hpp>
#include <kit/sprites/sprite_scene.hpp>

namespace kit {

/// The particle emitter number `index` makes now:
///  - point:  at position, direction uniform over the sphere (direction_in_cap(axis, 180°));
///  - disc:   at position + offset_in_disc(axis, radius), direction in the cap of angle_deg;
///  - sphere: at position + point_in_ball(radius).offset, flying along its .direction;
///  - cone:   at position, direction in the cap of angle_deg around axis.
/// Velocity = speed·direction, speed drawn from emitter.speed [m/s]; lifetime [s], size [m] and
/// alpha drawn from theirs; each colour channel from colour ± colour_variance. Colour and alpha
/// are clamped to [0, 1] and size to ≥ 0 (a draw may leave the range); emitter = index.
inline ParticleSpawn sample_particle(const Emitter& emitter, std::uint8_t index, Random& random) {
  ParticleSpawn p;
  // TODO(ex 5.1): place and aim by the shape, then draw speed, lifetime, size, colour and alpha as mean + rand·variance
  throw kit::NotImplemented("ex 5.1", "sprite_emit.hpp");
  return p;
}

}  // namespace kit
