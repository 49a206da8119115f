#pragma once
// A running sprite scene, frame by frame (Reeves 1983, §2): at the start of each frame every
// active emitter emits (ex 5.1 draws each particle), then every particle moves by Δt = 1/fps
// (particle_update.hpp), ages and, if dead, is removed (ex 5.2),
// and each death whose emitter has on_death bursts new particles where it died (fireworks).
// Counts are exact: alive = emitted − dead after every frame. A new particle starts a random
// fraction of its first step along its velocity, so one frame's particles do not move in a band.
#include <cstdint>
#include <vector>

#include <kit/base/random.hpp>
#include <kit/sprites/particle_update.hpp>
#include <kit/sprites/particles.hpp>
#include <kit/sprites/sprite_scene.hpp>

namespace kit {

/// The two steps a student writes (ex 5.1 and 5.2), plugged into the system by the chapter
/// (chapters/05-sprites/sprite_kernels.hpp): common/ never includes solutions/.
using SampleParticle = ParticleSpawn (*)(const Emitter& emitter, std::uint8_t index, Random& random);
using AgeAndKill = long (*)(Particles& particles, float dt, const DeathRules& rules,
                            const std::vector<bool>& bursts_on_death, std::vector<Death>& deaths);
struct SpriteKernels {
  SampleParticle sample;    ///< ex 5.1
  AgeAndKill age_and_kill;  ///< ex 5.2
};

/// What one frame did.
struct FrameCounts {
  long frame = 0;
  long emitted = 0;  ///< particles added this frame (per-frame emission and bursts)
  long died = 0;
  long dropped = 0;  ///< emissions refused because max_particles were alive
  long alive = 0;    ///< after the frame
};

/// Totals since the start; alive() == emitted − dead.
struct SpriteTotals {
  long emitted = 0, dead = 0, dropped = 0;
  long alive() const { return emitted - dead; }
};

class SpriteSystem {
 public:
  /// `scene` must outlive the system. Reserves max_particles once: no allocation per frame
  /// after the first bursts.
  SpriteSystem(const SpriteScene& scene, long max_particles, double fps, std::uint64_t seed,
               Integrator integrator, SpriteKernels kernels);
  /// Runs one frame: emit, update (Δt = 1/fps), bursts.
  FrameCounts step();
  const Particles& particles() const { return particles_; }
  const SpriteTotals& totals() const { return totals_; }
  const UpdateWork& work() const { return update_.work(); }
  long frame() const { return frame_; }
  double dt() const { return dt_; }

 private:
  long emit(std::size_t emitter, long count, const Death* parent);

  const SpriteScene& scene_;
  SpriteKernels kernels_;
  double dt_;
  Random random_;
  ParticleUpdate update_;
  Particles particles_;
  std::vector<Death> deaths_;  // reused every frame
  SpriteTotals totals_;
  long frame_ = 0;
  std::uint32_t next_id_ = 0;
  long dropped_this_frame_ = 0;
};

}  // namespace kit
