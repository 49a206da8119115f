// The student's program for sprite_emit.hpp (ex 5.1): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "sprite_emit.hpp"
#include "remote/fields/sprites.hpp"
#include "remote/student.hpp"

namespace {
/// n draws from the generator whose state the judge sent; the state goes back advanced.
std::vector<kit::ParticleSpawn> draw(const kit::Emitter& emitter, std::uint8_t index,
                                     kit::remote::RandomBytes& state, long n) {
  if (n < 0 || n > 1'000'000) throw std::invalid_argument("sample_particles: n out of range [0, 1e6]");
  kit::Random random(0);
  std::memcpy(static_cast<void*>(&random), state.data(), sizeof random);
  std::vector<kit::ParticleSpawn> particles;
  particles.reserve(std::size_t(n));
  for (long k = 0; k < n; ++k) particles.push_back(kit::sample_particle(emitter, index, random));
  std::memcpy(state.data(), static_cast<const void*>(&random), sizeof random);
  return particles;
}
}  // namespace

void register_entries(kit::remote::Entries& e) {
  e.add("sample_particle",
        [](const kit::Emitter& emitter, std::uint8_t index, kit::remote::RandomBytes& state) {
          return draw(emitter, index, state, 1).front();
        });
  e.add("sample_particles",
        [](const kit::Emitter& emitter, std::uint8_t index, kit::remote::RandomBytes& state, long n) {
          return draw(emitter, index, state, n);
        });
}
