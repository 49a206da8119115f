#pragma once
// Emission (Reeves 1983, §2.1): how many particles an emitter makes this frame, and the
// directions its shape allows. Drawing each particle's attributes is ex 5.1
// (solutions/sprite_emit.hpp), which uses these.
#include <cstdint>

#include <kit/base/random.hpp>
#include <kit/sprites/sprite_scene.hpp>

namespace kit {

/// Particles to emit this frame: N = mean + rand·variance (Reeves eq. 1), never negative. A
/// fractional N emits ⌊N⌋ and one more with probability N − ⌊N⌋, so the mean number per frame
/// is exactly E[max(N, 0)] even for rates below one particle per frame (fireworks shells).
long emission_count(const Spread& rate, Random& random);

/// mean + rand·variance, the draw of one scalar attribute.
inline double draw(const Spread& s, Random& random) { return s.mean + random.symmetric() * s.variance; }

/// A unit vector uniform over the cap of half-angle `angle_deg` around the unit vector `axis`
/// (180° is the whole sphere): cos θ uniform in [cos angle, 1], φ uniform in [0, 2π).
Vec3 direction_in_cap(const Vec3& axis, double angle_deg, Random& random);

/// A point uniform on the disc of `radius` [m] centred at the origin, normal to the unit `axis`:
/// r = R·√rand, so that equal areas are equally likely.
Vec3 offset_in_disc(const Vec3& axis, double radius, Random& random);

/// A point uniform in the ball of `radius` [m] centred at the origin, with its unit direction
/// from the centre (r = R·∛rand along a uniform direction). For the sphere shape, the direction
/// is also the particle's direction of flight.
struct BallPoint {
  Vec3 offset;     ///< [m]
  Vec3 direction;  ///< unit
};
BallPoint point_in_ball(double radius, Random& random);

}  // namespace kit
