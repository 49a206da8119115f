#include <kit/sprites/sprite_system.hpp>

#include <stdexcept>

#include <fmt/format.h>

#include <kit/sprites/emitter.hpp>

namespace kit {

SpriteSystem::SpriteSystem(const SpriteScene& scene, long max_particles, double fps, std::uint64_t seed,
                           Integrator integrator, SpriteKernels kernels)
    : scene_(scene), kernels_(kernels), dt_(1.0 / fps), random_(seed), update_(scene, integrator) {
  particles_.reserve(std::size_t(max_particles));
  deaths_.reserve(1024);
}

long SpriteSystem::emit(std::size_t index, long count, const Death* parent) {
  const Emitter& e = scene_.emitters[index];
  long added = 0;
  for (long k = 0; k < count; ++k) {
    ParticleSpawn p = kernels_.sample(e, std::uint8_t(index), random_);
    if (p.emitter != index)  // the rates, textures and bursts are looked up by this index
      throw std::logic_error(
          fmt::format("ex 5.1: sample_particle(emitter {0}) returned a particle of emitter {1}; "
                      "set its emitter to {0}",
                      index, p.emitter));
    if (parent) {  // a burst starts where its parent died, with part of its velocity
      const float keep = float(e.inherit_velocity);
      p.x += parent->x - float(e.position[0]), p.y += parent->y - float(e.position[1]);
      p.z += parent->z - float(e.position[2]);
      p.vx += keep * parent->vx, p.vy += keep * parent->vy, p.vz += keep * parent->vz;
    }
    // Particles of one frame would leave the emitter together and move in bands, one per frame.
    // Each is moved along its first step by a random fraction of Δt, as if it had been emitted
    // at that moment of the frame (to first order in Δt; its age and lifetime are unchanged).
    const float early = float(random_.unit() * dt_);
    p.x += early * p.vx, p.y += early * p.vy, p.z += early * p.vz;
    p.id = next_id_;
    if (!particles_.add(p)) {
      dropped_this_frame_ += count - k;
      break;
    }
    ++next_id_, ++added;
  }
  return added;
}

FrameCounts SpriteSystem::step() {
  FrameCounts c;
  c.frame = frame_;
  dropped_this_frame_ = 0;
  for (std::size_t i = 0; i < scene_.emitters.size(); ++i) {
    const Emitter& e = scene_.emitters[i];
    if (e.burst_only || frame_ < e.first_frame || (e.last_frame && frame_ > *e.last_frame)) continue;
    c.emitted += emit(i, emission_count(e.rate, random_), nullptr);
  }
  deaths_.clear();
  update_.step(particles_, dt_);
  const long alive = long(particles_.size());
  c.died = kernels_.age_and_kill(particles_, float(dt_), update_.death_rules(), update_.bursts_on_death(),
                                 deaths_);
  update_.count_deaths(alive, c.died);
  for (const Death& d : deaths_) {
    if (d.emitter >= scene_.emitters.size() || !scene_.emitters[d.emitter].on_death)
      throw std::logic_error(
          fmt::format("ex 5.2: age_and_kill recorded a death of emitter {}, which does not "
                      "burst; record only those with bursts_on_death[emitter]",
                      d.emitter));
    const int target = *scene_.emitters[d.emitter].on_death;
    c.emitted +=
        emit(std::size_t(target), emission_count(scene_.emitters[std::size_t(target)].rate, random_), &d);
  }
  c.dropped = dropped_this_frame_;
  totals_.emitted += c.emitted, totals_.dead += c.died, totals_.dropped += c.dropped;
  c.alive = long(particles_.size());
  ++frame_;
  return c;
}

}  // namespace kit
