#pragma once
// The judge's sprite_emit.hpp (ex 5.1): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <cstdint>
#include <vector>

#include <kit/base/random.hpp>
#include <kit/sprites/emitter.hpp>
#include <kit/sprites/particles.hpp>
#include <kit/sprites/sprite_scene.hpp>

#include "remote/fields/sprites.hpp"
#include "remote/judge.hpp"

namespace kit {
/// The generator travels as its state and comes back advanced by the student's draws.
inline ParticleSpawn sample_particle(const Emitter& emitter, std::uint8_t index, Random& random) {
  auto state = remote::bytes_of(random);
  const auto p = remote::call<ParticleSpawn>("sample_particle", emitter, index, remote::inout(state));
  remote::restore(random, state);
  return p;
}
}  // namespace kit

namespace kit::remote {
/// n draws of sample_particle with one generator, run in the student's program: the same
/// particles, in the same order, as n calls (a sample of 50 000 is one message, not 50 000).
inline std::vector<ParticleSpawn> sample_particles(const Emitter& emitter, std::uint8_t index, Random& random,
                                                   long n) {
  auto state = bytes_of(random);
  auto particles = call<std::vector<ParticleSpawn>>("sample_particles", emitter, index, inout(state), n);
  restore(random, state);
  return particles;
}
}  // namespace kit::remote
