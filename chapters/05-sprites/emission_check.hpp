#pragma once
// What a student's emission (ex 5.1) draws, measured: for each attribute, the mean and the
// half-width √(3·variance) of many draws, beside the scene's mean ± variance (Reeves's
// "variance" is the half-width of a uniform law, whose variance is half-width²/3).
#include <cstdint>
#include <string>
#include <vector>

#include <kit/sprites/sprite_system.hpp>

namespace kit {

struct AttributeDraws {
  std::string name;                             ///< "speed [m/s]", "lifetime [s]", "size [m]", "alpha"
  double mean = 0, half_width = 0;              ///< the scene's
  double drawn_mean = 0, drawn_half_width = 0;  ///< measured over the draws
};

/// `n` particles of `emitter` drawn by `sample` with a generator seeded by `seed`.
std::vector<AttributeDraws> measure_emission(const Emitter& emitter, SampleParticle sample,
                                             std::uint64_t seed, int n = 20000);

}  // namespace kit
