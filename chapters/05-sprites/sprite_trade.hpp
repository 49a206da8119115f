#pragma once
// The speed/accuracy trade of the sprite integrators (chapter 5): one particle launched like the
// scene's first emitter's mean particle, under the scene's gravity, drag and wind, followed for
// its mean lifetime with each integrator at several Δt, and its final position compared with
// the closed form (drag_motion.hpp). In double precision, so the orders show undisturbed; the
// particle arrays are float32, whose round-off (about 6e-8 of the position) is the floor a frame
// can show.
#include <vector>

#include <kit/sprites/particle_update.hpp>
#include <kit/sprites/sprite_scene.hpp>

namespace kit {

/// One particle's motion: start, forces, horizon.
struct DragProblem {
  Vec3 x0{0, 0, 0};       ///< [m]
  Vec3 v0{0, 0, 0};       ///< [m/s]
  Vec3 gravity{0, 0, 0};  ///< [m/s²]
  double drag = 0;        ///< k [1/s]
  Vec3 wind{0, 0, 0};     ///< [m/s]
  double t_end = 1;       ///< [s]

  /// The exact position at time t [s].
  Vec3 exact_position(double t) const;
};
/// The longest horizon of the trade [s]: 60 s take 460,000 steps at its smallest Δt.
inline constexpr double max_trade_horizon = 60.0;
/// The mean particle of `scene.emitters[0]` (at its position, along its axis at the mean speed),
/// under the scene's forces (absent ones are zero), for its mean lifetime (at most
/// max_trade_horizon).
DragProblem mean_particle(const SpriteScene& scene);

/// One run of the trade: n = round(t_end/Δt) steps, error |x_n − x(n·Δt)|.
struct TradeRun {
  double dt = 0;           ///< [s]
  long steps = 0;          ///< per particle over the horizon
  double error = 0;        ///< [m]
  Vec3 position{0, 0, 0};  ///< x_n [m]
  Vec3 exact{0, 0, 0};     ///< x(n·Δt) [m]
};
/// `integrator` on `problem` at each of `dts`.
std::vector<TradeRun> trade_runs(const DragProblem& problem, Integrator integrator,
                                 const std::vector<double>& dts);

/// An error below this is round-off, not the integrator's truncation: 100 × ε × steps × the
/// position's size, in [m]. Orders are fitted above it only.
double trade_roundoff(const TradeRun& run);

/// Δt = 1/15 s down to 1/3840 s, halving: frame rates from a slow preview to 128 substeps at 30 fps.
std::vector<double> trade_steps();

}  // namespace kit
