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
  // BEGIN SOLUTION ex 5.1: place and aim by the shape, then draw speed, lifetime, size, colour and alpha as mean + rand·variance
  Vec3 offset{0, 0, 0}, direction = emitter.axis;
  switch (emitter.shape) {
    case EmitterShape::point:
      direction = direction_in_cap(emitter.axis, 180.0, random);
      break;
    case EmitterShape::disc:
      offset = offset_in_disc(emitter.axis, emitter.radius, random);
      direction = direction_in_cap(emitter.axis, emitter.angle_deg, random);
      break;
    case EmitterShape::sphere: {
      const BallPoint at = point_in_ball(emitter.radius, random);
      offset = at.offset, direction = at.direction;
      break;
    }
    case EmitterShape::cone:
      direction = direction_in_cap(emitter.axis, emitter.angle_deg, random);
      break;
  }
  const double speed = draw(emitter.speed, random);
  const auto unit = [](double v) { return float(std::clamp(v, 0.0, 1.0)); };
  p.x = float(emitter.position[0] + offset[0]);
  p.y = float(emitter.position[1] + offset[1]);
  p.z = float(emitter.position[2] + offset[2]);
  p.vx = float(speed * direction[0]), p.vy = float(speed * direction[1]), p.vz = float(speed * direction[2]);
  p.lifetime = float(draw(emitter.lifetime, random));
  p.size = float(std::max(draw(emitter.size, random), 0.0));
  p.r = unit(emitter.colour[0] + random.symmetric() * emitter.colour_variance[0]);
  p.g = unit(emitter.colour[1] + random.symmetric() * emitter.colour_variance[1]);
  p.b = unit(emitter.colour[2] + random.symmetric() * emitter.colour_variance[2]);
  p.alpha = unit(draw(emitter.alpha, random));
  p.emitter = index;
  // END SOLUTION
  return p;
}

}  // namespace kit
