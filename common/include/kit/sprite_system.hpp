#pragma once
// A running sprite scene, frame by frame (Reeves 1983, §2): at the start of each frame every
// active emitter emits, then every particle moves and ages by Δt = 1/fps, the dead are removed,
// and each death whose emitter has on_death bursts new particles where it died (fireworks).
// Counts are exact: alive = emitted − dead after every frame.
#include <cstdint>
#include <vector>

#include <kit/particle_update.hpp>
#include <kit/particles.hpp>
#include <kit/sprite_random.hpp>
#include <kit/sprite_scene.hpp>

namespace kit {

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
               Integrator integrator);
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
  double dt_;
  SpriteRandom random_;
  ParticleUpdate update_;
  Particles particles_;
  std::vector<Death> deaths_;  // reused every frame
  SpriteTotals totals_;
  long frame_ = 0;
  std::uint32_t next_id_ = 0;
  long dropped_this_frame_ = 0;
};

}  // namespace kit
