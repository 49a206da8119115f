#include "rigid_drop.hpp"

#include <algorithm>
#include <cmath>

#include <kit/app/progress.hpp>
#include <kit/rigid/rigid_integrators.hpp>

namespace kit {

RigidState dropped_state(const RigidShape& shape, double height, double tilt_deg) {
  RigidState state;
  state.q = Quat(Eigen::AngleAxisd(tilt_deg * M_PI / 180, Vec3::UnitZ()));
  state.R = state.q.toRotationMatrix();
  state.x = Vec3(0, height + resting_height(shape, state.R), 0);
  return state;
}

double resting_height(const RigidShape& shape, const Mat3& R) {
  double lowest = HUGE_VAL;
  for (const Vec3& corner : shape.corners) lowest = std::min(lowest, (R * corner).y());
  return -lowest;
}

DropRun run_drop(const RigidKernels& kernels, RotationIntegrator integrator, const RigidShape& shape,
                 const RigidState& start, const GroundContact& contact, double h, double t_end, long frames) {
  DropRun run;
  const Vec3 weight(0, -shape.mass * contact.gravity, 0);  // [N]
  const long steps = std::max(1L, std::lround(t_end / h));
  const long sample_every = std::max(1L, steps / max_drop_samples);
  const auto sample = [&](const RigidState& s, double t) {
    return DropSample{t, s.x.y(), lowest_point(shape, s), kinetic_energy(shape, s),
                      shape.mass * contact.gravity * s.x.y()};
  };
  RigidState state = start;
  run.samples.push_back(sample(state, 0));
  if (frames > 0) run.frames.push_back(state);
  bool rising = false;  // after a bounce, until the next contact: the apex is the highest centre
  const double flat = resting_height(shape, Mat3::Identity());  // [m]
  ProgressCounter progress;
  for (long k = 1; k <= steps; ++k) {
    progress.add(1);
    const double t = double(k) * h;
    translation_step(shape, state, h, weight);
    rotation_step(kernels, integrator, shape, state, h);
    if (!state.R.allFinite() || !state.L.allFinite() || !state.x.allFinite()) {
      run.diverged_at = t;
      break;
    }
    const double before = sample(state, t).total();
    run.largest_turn = std::max(run.largest_turn, (state.R - start.R).norm());
    run.deepest = std::min(run.deepest, lowest_point(shape, state));
    const ContactEvent event = resolve_ground_contact(shape, state, contact);
    const DropSample now = sample(state, t);
    if (event.points > 0) {
      ++run.contacts;
      run.bounces += event.bounced;
      run.friction_impulse += event.friction_impulse;
      run.largest_gain = std::max(run.largest_gain, now.total() - before);
      run.most_sweeps = std::max(run.most_sweeps, event.sweeps);
      run.unconverged_contacts += event.sweeps >= max_contact_sweeps;
      run.largest_impulse_gain = std::max(run.largest_impulse_gain, event.kinetic_change);
      run.deepest_after = std::min(run.deepest_after, now.lowest);
      if (event.bounced) run.apexes.push_back(now.centre_height);
      rising = event.bounced;
    } else if (rising) {
      run.apexes.back() = std::max(run.apexes.back(), now.centre_height);
    }
    if (std::abs(state.x.y() - flat) > flat_tolerance) run.settled_at = t;
    if (k % sample_every == 0 || event.bounced) run.samples.push_back(now);
    if (frames > 0 && k == frame_step(long(run.frames.size()), steps, frames)) run.frames.push_back(state);
  }
  run.end = state;
  return run;
}

}  // namespace kit
