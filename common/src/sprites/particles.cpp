#include <kit/sprites/particles.hpp>

namespace kit {

void Particles::reserve(std::size_t n) {
  for (auto* a : {&x, &y, &z, &vx, &vy, &vz, &age, &lifetime, &size_m, &r, &g, &b, &alpha}) a->resize(n);
  emitter.resize(n);
  id.resize(n);
  if (count_ > n) count_ = n;
}

bool Particles::add(const ParticleSpawn& s) {
  if (full()) return false;
  const std::size_t i = count_++;
  x[i] = s.x, y[i] = s.y, z[i] = s.z;
  vx[i] = s.vx, vy[i] = s.vy, vz[i] = s.vz;
  age[i] = 0, lifetime[i] = s.lifetime, size_m[i] = s.size;
  r[i] = s.r, g[i] = s.g, b[i] = s.b, alpha[i] = s.alpha;
  emitter[i] = s.emitter;
  id[i] = s.id;
  return true;
}

void Particles::swap_remove(std::size_t i) {
  const std::size_t last = --count_;
  if (i == last) return;
  for (auto* a : {&x, &y, &z, &vx, &vy, &vz, &age, &lifetime, &size_m, &r, &g, &b, &alpha})
    (*a)[i] = (*a)[last];
  emitter[i] = emitter[last];
  id[i] = id[last];
}

}  // namespace kit
