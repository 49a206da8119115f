#pragma once
// Emission (Reeves 1983, §2.1–2.2): how many particles an emitter makes this frame, and the
// attributes of each, every one drawn as mean + rand·variance with rand uniform in [−1, 1].
#include <cstdint>

#include <kit/particles.hpp>
#include <kit/sprite_random.hpp>
#include <kit/sprite_scene.hpp>

namespace kit {

/// Particles to emit this frame: N = mean + rand·variance (Reeves eq. 1), never negative. A
/// fractional N emits ⌊N⌋ and one more with probability N − ⌊N⌋, so the mean number per frame
/// is exactly E[max(N, 0)] even for rates below one particle per frame (fireworks shells).
long emission_count(const Spread& rate, SpriteRandom& random);

/// mean + rand·variance, the draw of one scalar attribute.
inline double draw(const Spread& s, SpriteRandom& random) { return s.mean + random.symmetric() * s.variance; }

/// A unit vector uniform over the cap of half-angle `angle_deg` around the unit vector `axis`
/// (180° is the whole sphere): cos θ uniform in [cos angle, 1], φ uniform in [0, 2π).
Vec3d direction_in_cap(const Vec3d& axis, double angle_deg, SpriteRandom& random);

/// One new particle of `emitter` (its index `index`), placed and aimed by its shape, every
/// attribute drawn from its Spread; colour and alpha are clamped to [0, 1], size to ≥ 0.
ParticleSpawn sample_particle(const Emitter& emitter, std::uint8_t index, SpriteRandom& random);

}  // namespace kit
