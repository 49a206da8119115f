#include <kit/sprites/particle_update.hpp>

#include <algorithm>
#include <cstddef>

#include <kit/sprites/drag_motion.hpp>

namespace kit {

int order(Integrator i) {
  switch (i) {
    case Integrator::explicit_euler:
    case Integrator::symplectic_euler:
      return 1;
    case Integrator::midpoint:
      return 2;
    case Integrator::exact:
      return 0;
  }
  return 0;
}

AxisStep axis_step(Integrator i, double k, double h, double gravity, double wind) {
  const double c = gravity + k * wind;  // a(v) = c − k v
  switch (i) {
    case Integrator::explicit_euler:  // x' = x + h v, v' = (1 − hk) v + h c
      return {h, 0, 1 - h * k, h * c};
    case Integrator::symplectic_euler:  // v' = (1 − hk) v + h c, then x' = x + h v'
      return {h * (1 - h * k), h * h * c, 1 - h * k, h * c};
    case Integrator::midpoint: {  // v½ = (1 − hk/2) v + h c/2; x' = x + h v½; v' = v + h (c − k v½)
      const double half = 1 - h * k / 2;
      return {h * half, h * h * c / 2, 1 - h * k * half, h * c * half};
    }
    case Integrator::exact: {
      const DragStep d(k, h);
      return {d.f, (h - d.f) * wind + d.g * gravity, d.e, d.f * c};
    }
  }
  return {};
}

ParticleUpdate::ParticleUpdate(const SpriteScene& scene, Integrator integrator) : integrator_(integrator) {
  if (scene.forces.gravity) has_gravity_ = true, gravity_ = *scene.forces.gravity;
  if (scene.forces.drag) has_drag_ = true, drag_ = *scene.forces.drag;
  if (scene.forces.wind) wind_ = *scene.forces.wind;
  for (const Emitter& e : scene.emitters) {
    rates_.push_back({float(e.colour_rate[0]), float(e.colour_rate[1]), float(e.colour_rate[2]),
                      float(e.alpha_rate), float(e.size_rate)});
    has_colour_rate_ |= e.colour_rate != Colour{0, 0, 0};
    has_alpha_rate_ |= e.alpha_rate != 0;
    has_size_rate_ |= e.size_rate != 0;
    bursts_on_death_.push_back(e.on_death.has_value());
  }
  death_ = scene.death;
}

namespace {
// One axis of every particle through x' = x + p v + q, v' = r v + s. The three loops are the
// same map with the terms a scene does not have left out: no force (drift), gravity alone
// (r = 1), drag (the general case). Plain loops over restrict pointers: the compiler vectorises.
enum class Motion { drift, accelerate, drag };
template <Motion M>
void move_axis(float* __restrict x, float* __restrict v, std::size_t n, const AxisStep& a) {
  const float p = float(a.p), q = float(a.q), r = float(a.r), s = float(a.s);
  for (std::size_t i = 0; i < n; ++i) {
    if constexpr (M == Motion::drift) {
      x[i] += p * v[i];
    } else if constexpr (M == Motion::accelerate) {
      x[i] += p * v[i] + q;
      v[i] += s;
    } else {
      x[i] += p * v[i] + q;
      v[i] = r * v[i] + s;
    }
  }
}
}  // namespace

void ParticleUpdate::move(Particles& ps, double h) {
  const std::size_t n = ps.size();
  float* x[] = {ps.x.data(), ps.y.data(), ps.z.data()};
  float* v[] = {ps.vx.data(), ps.vy.data(), ps.vz.data()};
  for (int axis = 0; axis < 3; ++axis) {
    const AxisStep a = axis_step(integrator_, drag_, h, gravity_[axis], wind_[axis]);
    if (has_drag_)
      move_axis<Motion::drag>(x[axis], v[axis], n, a);
    else if (has_gravity_ && gravity_[axis] != 0)
      move_axis<Motion::accelerate>(x[axis], v[axis], n, a);
    else
      move_axis<Motion::drift>(x[axis], v[axis], n, a);
  }
  work_.particle_steps += long(n);
  if (has_gravity_) work_.gravity += long(n);
  if (has_drag_) work_.drag += long(n);
}

void ParticleUpdate::change_attributes(Particles& ps, double h) {
  const std::size_t n = ps.size();
  const float dt = float(h);
  const std::uint8_t* e = ps.emitter.data();
  if (has_colour_rate_) {
    for (std::size_t i = 0; i < n; ++i) {
      const Rates& rate = rates_[e[i]];
      ps.r[i] = std::clamp(ps.r[i] + rate.r * dt, 0.f, 1.f);
      ps.g[i] = std::clamp(ps.g[i] + rate.g * dt, 0.f, 1.f);
      ps.b[i] = std::clamp(ps.b[i] + rate.b * dt, 0.f, 1.f);
    }
    work_.colour += long(n);
  }
  if (has_alpha_rate_) {
    for (std::size_t i = 0; i < n; ++i)
      ps.alpha[i] = std::clamp(ps.alpha[i] + rates_[e[i]].alpha * dt, 0.f, 1.f);
    work_.alpha += long(n);
  }
  if (has_size_rate_) {
    for (std::size_t i = 0; i < n; ++i) ps.size_m[i] = std::max(ps.size_m[i] + rates_[e[i]].size * dt, 0.f);
    work_.size += long(n);
  }
}

void ParticleUpdate::count_deaths(long alive, long died) {
  if (death_.alpha_below) work_.alpha_checks += alive;
  if (death_.region) work_.region_checks += alive;
  work_.deaths += died;
}

void ParticleUpdate::step(Particles& particles, double h) {
  move(particles, h);
  change_attributes(particles, h);
}

}  // namespace kit
