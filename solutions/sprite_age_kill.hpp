#pragma once
// Ex 5.2: the end of a frame for every particle (Reeves 1983, §2.4): it ages by Δt, and it dies
// when its age reaches its lifetime, when it fades below the scene's opacity threshold, or when
// it leaves the scene's region. A dead particle is removed by swap-remove: the last alive
// particle moves into its slot, so the arrays stay dense and nothing is allocated.
#include <cstddef>
#include <vector>

#include <kit/base/not_implemented.hpp>
#include <kit/sprites/particle_update.hpp>
#include <kit/sprites/particles.hpp>
#include <kit/sprites/sprite_scene.hpp>

namespace kit {

/// Adds dt [s] to every alive particle's age, then removes each particle with
///   age ≥ lifetime,  or  alpha < rules.alpha_below (when set),
///   or  a position outside rules.region = [min, max] on some axis (when set).
/// A dead particle whose emitter e has bursts_on_death[e] is appended to `deaths` (position,
/// velocity, emitter) before it is removed. Remove with particles.swap_remove(i), and test slot i
/// again: it now holds the particle that was last. Returns the number of particles removed.
inline long age_and_kill(Particles& particles, float dt, const DeathRules& rules,
                         const std::vector<bool>& bursts_on_death, std::vector<Death>& deaths) {
  long removed = 0;
  // BEGIN SOLUTION ex 5.2: age every particle, then scan: a dead one is recorded if it bursts, swap-removed, and its slot tested again
  for (std::size_t i = 0; i < particles.size(); ++i) particles.age[i] += dt;
  const auto outside = [&](std::size_t i) {
    const auto& [lo, hi] = *rules.region;
    return particles.x[i] < lo[0] || particles.x[i] > hi[0] || particles.y[i] < lo[1] ||
           particles.y[i] > hi[1] || particles.z[i] < lo[2] || particles.z[i] > hi[2];
  };
  for (std::size_t i = 0; i < particles.size();) {
    const bool dies = particles.age[i] >= particles.lifetime[i] ||
                      (rules.alpha_below && particles.alpha[i] < float(*rules.alpha_below)) ||
                      (rules.region && outside(i));
    if (!dies) {
      ++i;
      continue;
    }
    if (bursts_on_death[particles.emitter[i]])
      deaths.push_back({particles.x[i], particles.y[i], particles.z[i], particles.vx[i], particles.vy[i],
                        particles.vz[i], particles.emitter[i]});
    particles.swap_remove(i);
    ++removed;
  }
  // END SOLUTION
  return removed;
}

}  // namespace kit
