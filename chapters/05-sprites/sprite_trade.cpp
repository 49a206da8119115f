#include "sprite_trade.hpp"

#include <algorithm>
#include <cmath>

#include <kit/sprites/drag_motion.hpp>

namespace kit {

Vec3 DragProblem::exact_position(double t) const {
  Vec3 x;
  for (int i = 0; i < 3; ++i) x[i] = drag_motion({x0[i], v0[i]}, gravity[i], drag, wind[i], t).x;
  return x;
}

DragProblem mean_particle(const SpriteScene& scene) {
  DragProblem p;
  const Emitter& e = scene.emitters.at(0);
  p.x0 = e.position;
  for (int i = 0; i < 3; ++i) p.v0[i] = e.speed.mean * e.axis[i];
  if (scene.forces.gravity) p.gravity = *scene.forces.gravity;
  if (scene.forces.drag) p.drag = *scene.forces.drag;
  if (scene.forces.wind) p.wind = *scene.forces.wind;
  p.t_end = std::min(e.lifetime.mean, max_trade_horizon);
  return p;
}

std::vector<TradeRun> trade_runs(const DragProblem& problem, Integrator integrator,
                                 const std::vector<double>& dts) {
  std::vector<TradeRun> runs;
  for (const double dt : dts) {
    TradeRun run;
    run.dt = dt;
    run.steps = std::max(1L, std::lround(problem.t_end / dt));
    double squared = 0;
    run.exact = problem.exact_position(double(run.steps) * dt);
    for (int i = 0; i < 3; ++i) {
      const AxisStep a = axis_step(integrator, problem.drag, dt, problem.gravity[i], problem.wind[i]);
      double x = problem.x0[i], v = problem.v0[i];
      for (long k = 0; k < run.steps; ++k) x += a.p * v + a.q, v = a.r * v + a.s;  // the particle loop's map
      run.position[i] = x;
      squared += (x - run.exact[i]) * (x - run.exact[i]);
    }
    run.error = std::sqrt(squared);
    runs.push_back(run);
  }
  return runs;
}

double trade_roundoff(const TradeRun& run) {
  const double size = 1.0 + std::hypot(run.exact[0], run.exact[1], run.exact[2]);
  return 100.0 * 2.2e-16 * double(run.steps) * size;
}

std::vector<double> trade_steps() {
  std::vector<double> dts;
  for (double dt = 1.0 / 15; dt > 1.0 / 4000; dt /= 2) dts.push_back(dt);
  return dts;
}

}  // namespace kit
