#include "emission_check.hpp"

#include <cmath>

namespace kit {

std::vector<AttributeDraws> measure_emission(const Emitter& emitter, SampleParticle sample,
                                             std::uint64_t seed, int n) {
  std::vector<AttributeDraws> out{{"speed [m/s]", emitter.speed.mean, emitter.speed.variance},
                                  {"lifetime [s]", emitter.lifetime.mean, emitter.lifetime.variance},
                                  {"size [m]", emitter.size.mean, emitter.size.variance},
                                  {"alpha", emitter.alpha.mean, emitter.alpha.variance}};
  std::vector<double> sum(out.size(), 0.0), squares(out.size(), 0.0);
  Random random(seed);
  for (int k = 0; k < n; ++k) {
    const ParticleSpawn p = sample(emitter, 0, random);
    const double values[] = {std::hypot(p.vx, p.vy, p.vz), p.lifetime, p.size, p.alpha};
    for (std::size_t a = 0; a < out.size(); ++a) sum[a] += values[a], squares[a] += values[a] * values[a];
  }
  for (std::size_t a = 0; a < out.size(); ++a) {
    const double mean = sum[a] / n, variance = std::max(0.0, squares[a] / n - mean * mean);
    out[a].drawn_mean = mean;
    out[a].drawn_half_width = std::sqrt(3.0 * variance);
  }
  return out;
}

}  // namespace kit
