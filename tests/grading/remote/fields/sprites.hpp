#pragma once
// How the sprite chapter's types cross the link (wire.hpp): kit/sprites/sprite_scene.hpp,
// kit/sprites/particles.hpp, kit/sprites/particle_update.hpp (Death) and kit/sprites/sprite_random.hpp.
#include <array>
#include <cstring>
#include <sstream>
#include <tuple>

#include <kit/base/random.hpp>
#include <kit/sprites/particles.hpp>
#include <kit/sprites/sprite_scene.hpp>

#include "../wire.hpp"

namespace kit {
inline auto fields(Spread& s) { return std::tie(s.mean, s.variance); }
inline auto fields(Emitter& e) {
  return std::tie(e.name, e.shape, e.position, e.axis, e.radius, e.angle_deg, e.rate, e.speed, e.lifetime,
                  e.size, e.colour, e.colour_variance, e.alpha, e.colour_rate, e.alpha_rate, e.size_rate,
                  e.blend, e.texture, e.burst_only, e.on_death, e.inherit_velocity, e.first_frame,
                  e.last_frame);
}
inline auto fields(DeathRules& d) { return std::tie(d.alpha_below, d.region); }
inline auto fields(ParticleSpawn& p) {
  return std::tie(p.x, p.y, p.z, p.vx, p.vy, p.vz, p.lifetime, p.size, p.r, p.g, p.b, p.alpha, p.emitter,
                  p.id);
}
}  // namespace kit

namespace kit::remote {
/// Particles: capacity and count, then every array at its full capacity. The count is rebuilt
/// through add() (it is private), and each array must arrive at the capacity's length.
template <>
struct Codec<Particles> {
  /// Calls f(a's array, b's array) for each of the particles' arrays, in one order.
  template <class F>
  static void each_pair(Particles& a, Particles& b, F&& f) {
    f(a.x, b.x), f(a.y, b.y), f(a.z, b.z), f(a.vx, b.vx), f(a.vy, b.vy), f(a.vz, b.vz), f(a.age, b.age);
    f(a.lifetime, b.lifetime), f(a.size_m, b.size_m), f(a.r, b.r), f(a.g, b.g), f(a.b, b.b),
        f(a.alpha, b.alpha);
    f(a.emitter, b.emitter), f(a.id, b.id);
  }
  template <class F>
  static void each_array(Particles& p, F&& f) {
    each_pair(p, p, [&](auto& array, auto&) { f(array); });
  }
  static void put(Writer& w, const Particles& p) {
    w.scalar(std::uint64_t(p.capacity())), w.scalar(std::uint64_t(p.size()));
    each_array(const_cast<Particles&>(p), [&](auto& array) { remote::put(w, array); });
  }
  static void get(Reader& r, Particles& p) {
    const auto capacity = r.scalar<std::uint64_t>(), count = r.scalar<std::uint64_t>();
    if (count > capacity || capacity > r.left() / Particles::bytes_per_particle)
      throw ProtocolError("particles that do not fit their message");
    p = Particles();
    p.reserve(std::size_t(capacity));
    for (std::uint64_t i = 0; i < count; ++i) p.add(ParticleSpawn{});
    each_array(p, [&](auto& array) {
      remote::get(r, array);
      if (array.size() != capacity) throw ProtocolError("a particle array that is not the capacity long");
    });
  }
};

/// The generator's state, as bytes (it is private). What comes back from a student's program is
/// checked before the judge draws from it: the engine's position must lie in its state.
using RandomBytes = std::array<unsigned char, sizeof(Random)>;
inline RandomBytes bytes_of(const Random& random) {
  RandomBytes bytes;
  std::memcpy(bytes.data(), &random, sizeof random);
  return bytes;
}
inline void restore(Random& random, const RandomBytes& bytes) {
  static_assert(sizeof(Random) == sizeof(std::mt19937_64));
  std::mt19937_64 engine;
  std::memcpy(static_cast<void*>(&engine), bytes.data(), sizeof engine);
  std::ostringstream text;
  text << engine;  // the n words of state, then the position (libstdc++)
  const std::string state = text.str();
  const auto position = std::stoull(state.substr(state.find_last_of(' ') + 1));
  if (position > std::mt19937_64::state_size)
    throw ProtocolError("a random generator in an impossible state");
  std::memcpy(static_cast<void*>(&random), bytes.data(), sizeof random);
}
}  // namespace kit::remote
