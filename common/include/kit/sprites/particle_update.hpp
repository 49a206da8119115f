#pragma once
// The motion of a sprite scene over one frame of Δt (lecture, "Sprites": a particle falls under
// gravity), and the change of colour, opacity and size at their rates (Reeves 1983, §2.3). The
// ageing and the deaths are ex 5.2 (solutions/sprite_age_kill.hpp), which SpriteSystem runs
// after these. Only what the scene lists is computed: a scene without drag runs a loop with no
// drag term, and UpdateWork counts what each step did.
//
// The force a = g − k (v − w) is linear in v, so one step of any of the four integrators is the
// same affine map per axis, x' = x + p·v + q, v' = r·v + s, with coefficients that depend only on
// the integrator, Δt, k, g and w (see axis_step). The integrators cost the same per particle; they
// differ in accuracy only. The particle loop is one pass over contiguous float arrays.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <kit/base/enum_names.hpp>
#include <kit/sprites/particles.hpp>
#include <kit/sprites/sprite_scene.hpp>

namespace kit {

enum class Integrator { explicit_euler, symplectic_euler, midpoint, exact };
/// The --integrator names, and the names figures show.
inline constexpr auto integrator_names = enum_names<Integrator>({
    {Integrator::explicit_euler, "euler", "explicit Euler"},
    {Integrator::symplectic_euler, "symplectic", "symplectic Euler"},
    {Integrator::midpoint, "midpoint", "midpoint RK2"},
    {Integrator::exact, "exact", "exact (closed form)"},
});
static_assert(integrator_names.in_order());
inline constexpr auto all_integrators = integrator_names.all();
inline std::string_view flag_name(Integrator integrator) { return integrator_names.flag(integrator); }
inline std::string_view display_name(Integrator integrator) { return integrator_names.display(integrator); }
/// Global order of the position error (0 for the exact step: round-off only).
int order(Integrator integrator);

/// One axis of one step: x' = x + p·v + q [m], v' = r·v + s [m/s].
struct AxisStep {
  double p = 0;  ///< [s]
  double q = 0;  ///< [m]
  double r = 1;  ///< dimensionless
  double s = 0;  ///< [m/s]
};
/// The step of `integrator` over h [s] for dv/dt = gravity − k (v − wind) on one axis:
///  explicit Euler   x' = x + h v,                 v' = v + h a(v);
///  symplectic Euler v' = v + h a(v),              x' = x + h v';
///  midpoint RK2     v½ = v + h/2 a(v),            x' = x + h v½,  v' = v + h a(v½);
///  exact            drag_motion.hpp's closed form.
AxisStep axis_step(Integrator integrator, double k, double h, double gravity, double wind);

/// A particle that died this step, for its emitter's on_death burst.
struct Death {
  float x, y, z, vx, vy, vz;
  std::uint8_t emitter;
};

/// What the updates did so far, in particle-steps: each counter grows by the number of particles
/// a step applied that term to. A term the scene does not list stays at 0.
struct UpdateWork {
  long particle_steps = 0;  ///< every particle, every step (motion)
  long gravity = 0;
  long drag = 0;                             ///< drag, and wind through it
  long colour = 0, alpha = 0, size = 0;      ///< rates of change over life
  long alpha_checks = 0, region_checks = 0;  ///< death tests beyond the lifetime
  long deaths = 0;
};

class ParticleUpdate {
 public:
  ParticleUpdate(const SpriteScene& scene, Integrator integrator);
  /// Moves every alive particle by h [s] and applies the rates of change of its emitter.
  void step(Particles& particles, double h);
  /// Counts the death tests that ex 5.2's pass made over `alive` particles, and its `died`.
  void count_deaths(long alive, long died);
  const UpdateWork& work() const { return work_; }
  Integrator integrator() const { return integrator_; }
  const DeathRules& death_rules() const { return death_; }
  /// Per emitter: whether its deaths burst (on_death), so the death pass records them.
  const std::vector<bool>& bursts_on_death() const { return bursts_on_death_; }

 private:
  struct Rates {
    float r = 0, g = 0, b = 0, alpha = 0, size = 0;
  };
  void move(Particles& particles, double h);
  void change_attributes(Particles& particles, double h);

  Integrator integrator_;
  Vec3 gravity_{0, 0, 0}, wind_{0, 0, 0};
  double drag_ = 0;
  bool has_gravity_ = false, has_drag_ = false;
  bool has_colour_rate_ = false, has_alpha_rate_ = false, has_size_rate_ = false;
  std::vector<Rates> rates_;           // per emitter [1/s], [m/s]
  std::vector<bool> bursts_on_death_;  // per emitter
  DeathRules death_;
  UpdateWork work_;
};

}  // namespace kit
