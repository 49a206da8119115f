#include "rigid_experiments.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>

#include <kit/app/progress.hpp>
#include <kit/rigid/rigid_free_rotation.hpp>
#include <kit/rigid/rigid_reference.hpp>

namespace kit {
namespace {

double relative(double value, double start) { return start == 0 ? value : (value - start) / start; }

RotationSample sample_of(const RigidShape& shape, const RigidState& state, double t, double e0, double l0) {
  return {t,
          body_angular_velocity(shape, state),
          relative(rotational_energy(shape, state), e0),
          relative(state.L.norm(), l0),
          relative(body_momentum(state).norm(), l0),
          orthonormality_error(state.R)};
}

bool finite(const RigidState& state) { return state.R.allFinite() && state.L.allFinite(); }

}  // namespace

std::array<int, 3> axes_by_moment(const RigidShape& shape) {
  std::array<int, 3> axes{0, 1, 2};
  std::sort(axes.begin(), axes.end(),
            [&](int a, int b) { return shape.inertia(a, a) < shape.inertia(b, b); });
  return axes;
}

int intermediate_axis(const RigidShape& shape) { return axes_by_moment(shape)[1]; }

bool FlipCounter::add(double t, const Vec3& omega_body) {
  const double along = omega_body[axis_];
  if (started_ && (along < 0) != (before_ < 0) && along != before_)
    crossed_ = t - (t - before_t_) * along / (along - before_);
  started_ = true;
  before_ = along, before_t_ = t;
  if (!(std::abs(along) > 0.5 * omega_body.norm())) return false;
  const int side = along > 0 ? 1 : -1;
  const bool flipped = side_ != 0 && side != side_;
  if (flipped) times_.push_back(crossed_);
  side_ = side;
  return flipped;
}

double RotationRun::flip_interval() const {
  if (flip_times.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  return (flip_times.back() - flip_times.front()) / double(flip_times.size() - 1);
}

RotationRun run_free_rotation(const RigidKernels& kernels, RotationIntegrator integrator,
                              const RigidShape& shape, const RigidState& start, double h, double t_end,
                              long max_samples, long frames) {
  RotationRun run;
  run.integrator = integrator;
  run.h = h;
  run.steps = std::max(1L, std::lround(t_end / h));
  const long stride = std::max(1L, run.steps / std::max(1L, max_samples - 1));
  const double e0 = rotational_energy(shape, start), l0 = start.L.norm();
  RigidState state = start;
  run.samples.push_back(sample_of(shape, state, 0, e0, l0));
  if (frames > 0) run.frames.push_back(state);
  FlipCounter flips(intermediate_axis(shape));
  flips.add(0, run.samples.back().omega_body);
  ProgressCounter progress;
  for (long k = 1; k <= run.steps; ++k) {
    run.unconverged_steps += rotation_step(kernels, integrator, shape, state, h) ? 0 : 1;
    progress.add(1);
    const double t = double(k) * h;
    if (!finite(state)) {
      run.diverged_at = t;
      break;
    }
    const RotationSample now = sample_of(shape, state, t, e0, l0);
    flips.add(t, now.omega_body);
    run.max_energy_drift = std::max(run.max_energy_drift, std::abs(now.energy_drift));
    run.max_momentum_drift = std::max(run.max_momentum_drift, std::abs(now.momentum_drift));
    run.max_body_momentum_drift = std::max(run.max_body_momentum_drift, std::abs(now.body_momentum_drift));
    run.max_orthonormality = std::max(run.max_orthonormality, now.orthonormality);
    if (k % stride == 0 || k == run.steps) run.samples.push_back(now);
    if (frames > 0 && k == frame_step(long(run.frames.size()), run.steps, frames))
      run.frames.push_back(state);
  }
  run.flip_times = flips.times();
  run.end = state;
  return run;
}

double closed_form_flip_interval(const RigidShape& shape, const RigidState& start) {
  const auto axes = axes_by_moment(shape);
  const Vec3 omega = body_angular_velocity(shape, start);
  const Vec3 moments(shape.inertia(axes[0], axes[0]), shape.inertia(axes[1], axes[1]),
                     shape.inertia(axes[2], axes[2]));
  return free_rotation(moments, Vec3(omega[axes[0]], omega[axes[1]], omega[axes[2]])).period() / 2;
}

std::vector<AxisSpin> spins_about_axes(const RigidShape& shape, double t_end) {
  std::vector<AxisSpin> spins;
  for (int axis : axes_by_moment(shape)) {
    AxisSpin spin;
    spin.axis = axis;
    spin.moment = shape.inertia(axis, axis);
    Vec3 omega = Vec3::Zero();
    omega[axis] = 10;             // [rad/s]
    omega[(axis + 2) % 3] = 0.1;  // the disturbance, 1% of the spin
    spin.run = run_free_rotation({}, RotationIntegrator::rk4, shape,
                                 spinning_state(shape, Vec3::Zero(), omega), 1e-3, t_end);
    FlipCounter flips(axis);
    for (const auto& sample : spin.run.samples) {
      const Vec3& w = sample.omega_body;
      const double cosine = std::min(1.0, std::abs(w[axis]) / w.norm());
      spin.max_deviation_deg = std::max(spin.max_deviation_deg, std::acos(cosine) * 180 / M_PI);
      flips.add(sample.t, w);
    }
    spin.flips_about_axis = long(flips.times().size());
    spins.push_back(std::move(spin));
  }
  return spins;
}

RotationTrade rotation_trade(const RigidKernels& kernels, const std::vector<RotationIntegrator>& integrators,
                             const RigidShape& shape, const RigidState& start, double t_end,
                             const std::vector<long>& step_counts) {
  RotationTrade trade;
  trade.t_end = t_end;
  Stats stats;
  const Mat3 reference = free_rotation_reference(shape, start, {t_end}, &stats).front().R;
  trade.reference_evaluations = stats.rhs_evals;
  for (RotationIntegrator integrator : integrators) {
    std::vector<RotationTradePoint> curve;
    for (long steps : step_counts) {
      const double h = t_end / double(steps);
      RigidState state = start;
      const auto began = std::chrono::steady_clock::now();
      for (long k = 0; k < steps; ++k) rotation_step(kernels, integrator, shape, state, h);
      const std::chrono::duration<double> took = std::chrono::steady_clock::now() - began;
      curve.push_back({steps, h, took.count(), (state.R - reference).norm()});
    }
    trade.curves.emplace_back(integrator, std::move(curve));
  }
  return trade;
}

double reference_sampling(const RigidShape& shape, const RigidState& start) {
  return std::min(1e-3, 0.05 / body_angular_velocity(shape, start).norm());
}

std::vector<double> reference_flip_times(const RigidShape& shape, const RigidState& start, double t_end) {
  // 10⁴ samples at a time from where the last chunk ended, so that a long run keeps one chunk of
  // states, not all of them.
  const double every = reference_sampling(shape, start);  // [s]
  constexpr long chunk = 10'000;
  const long samples = std::lround(t_end / every);
  FlipCounter flips(intermediate_axis(shape));
  flips.add(0, body_angular_velocity(shape, start));
  RigidState from = start;
  for (long first = 1; first <= samples; first += chunk) {
    std::vector<double> times;
    for (long k = first; k < first + chunk && k <= samples; ++k)
      times.push_back(double(k - first + 1) * every);
    const auto states = free_rotation_reference(shape, from, times);
    for (std::size_t k = 0; k < states.size(); ++k)
      flips.add(double(first + long(k)) * every, body_angular_velocity(shape, states[k]));
    from = states.back();
  }
  return flips.times();
}

std::vector<FlipSweepRow> flip_sweep(const RigidKernels& kernels,
                                     const std::vector<RotationIntegrator>& integrators,
                                     const RigidShape& shape, const RigidState& start, double t_end,
                                     const std::vector<double>& steps) {
  std::vector<FlipSweepRow> rows;
  for (RotationIntegrator integrator : integrators)
    for (double h : steps) {
      const RotationRun run = run_free_rotation(kernels, integrator, shape, start, h, t_end, 2);
      rows.push_back({integrator, h, long(run.flip_times.size()), run.flip_interval(), run.max_energy_drift,
                      run.diverged_at >= 0});
    }
  return rows;
}

}  // namespace kit
