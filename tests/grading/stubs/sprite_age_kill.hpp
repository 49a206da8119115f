#pragma once
// The judge's sprite_age_kill.hpp (ex 5.2): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <algorithm>
#include <utility>
#include <vector>

#include <kit/sprites/particle_update.hpp>
#include <kit/sprites/particles.hpp>
#include <kit/sprites/sprite_scene.hpp>

#include "remote/fields/death.hpp"
#include "remote/judge.hpp"

namespace kit {
/// The particles come back as the student's function left them; when it kept their storage (no
/// array reallocated, which the student's program reports), they are copied into the judge's own
/// storage, and otherwise replace it, so that a test of "nothing reallocated" sees what happened.
inline long age_and_kill(Particles& particles, float dt, const DeathRules& rules,
                         const std::vector<bool>& bursts_on_death, std::vector<Death>& deaths) {
  Particles after;
  const auto [removed, kept_storage] = remote::call<std::pair<long, bool>>(
      "age_and_kill", remote::replaced(particles, after), dt, rules, bursts_on_death, remote::inout(deaths));
  if (!kept_storage || after.capacity() != particles.capacity()) {
    particles = std::move(after);
    return removed;
  }
  particles.clear();
  for (std::size_t i = 0; i < after.size(); ++i) particles.add(ParticleSpawn{});
  remote::Codec<Particles>::each_pair(
      after, particles, [](auto& from, auto& to) { std::copy(from.begin(), from.end(), to.begin()); });
  return removed;
}
}  // namespace kit
