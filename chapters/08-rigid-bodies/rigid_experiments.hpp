#pragma once
// What chapter 8 measures on the free body: one integrator's run of the torque-free rotation
// (the flips of the intermediate axis, the drift of E and |L|, RᵀR − I), how the flips depend on
// the step, which principal axes are stable, and the error in R after T against its cost.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include <kit/rigid/rigid_stepper.hpp>

namespace kit {

/// The body axis (0, 1, 2 = x, y, z) of the middle principal moment: the shapes' inertia is
/// diagonal in their body axes, so its principal axes are the body axes.
int intermediate_axis(const RigidShape& shape);
/// The body axes ordered by their moments, smallest first.
std::array<int, 3> axes_by_moment(const RigidShape& shape);

/// Counts flips: ω along one body axis reversing while it is the larger part of ω (|ω_a| > ½|ω|
/// on both sides), timed at the zero crossing between. A wobble about another axis (a stable
/// spin, or a body a first-order step has moved to its smallest axis) is no flip.
class FlipCounter {
 public:
  explicit FlipCounter(int axis) : axis_(axis) {}
  /// Takes ω in the body frame at time t [s]; true when a flip ended there.
  bool add(double t, const Vec3& omega_body);
  const std::vector<double>& times() const { return times_; }

 private:
  int axis_;
  int side_ = 0;  // the sign of ω along the axis when last dominant; 0 before
  double before_ = 0, before_t_ = 0, crossed_ = 0;
  bool started_ = false;
  std::vector<double> times_;
};

/// One moment of a run: ω in the body frame and how far the invariants have drifted.
struct RotationSample {
  double t = 0;                    ///< [s]
  Vec3 omega_body = Vec3::Zero();  ///< I_body⁻¹ Rᵀ L [rad/s]
  double energy_drift = 0;         ///< (E − E0)/E0
  double momentum_drift = 0;       ///< (|L| − |L0|)/|L0|, L in the world frame
  double body_momentum_drift = 0;  ///< (|RᵀL| − |L0|)/|L0|: what an R off SO(3) makes of L
  double orthonormality = 0;       ///< ‖RᵀR − I‖
};

struct RotationRun {
  RotationIntegrator integrator{};
  double h = 0;  ///< [s]
  long steps = 0;
  std::vector<RotationSample> samples;  ///< evenly spaced, first and last step included
  std::vector<double> flip_times;       ///< [s] the flips of the intermediate axis (FlipCounter)
  double max_energy_drift = 0, max_momentum_drift = 0, max_orthonormality = 0;  ///< |…| over the run
  double max_body_momentum_drift = 0;                                           ///< |…| over the run
  long unconverged_steps = 0;      ///< midpoint steps split because the fixed point stalled
  double diverged_at = -1;         ///< [s] when a value stopped being finite; −1 if never
  std::vector<RigidState> frames;  ///< evenly spaced states for pictures, when asked for
  RigidState end;

  /// Mean time between consecutive flips [s]; NaN with fewer than two.
  double flip_interval() const;
};

/// Runs `integrator` from `start` for t_end [s] at step h, no torque, keeping at most
/// `max_samples` samples and `frames` + 1 states evenly spaced in time (none when 0). Throws
/// NotImplemented as rotation_step does.
RotationRun run_free_rotation(const RigidKernels& kernels, RotationIntegrator integrator,
                              const RigidShape& shape, const RigidState& start, double h, double t_end,
                              long max_samples = 2000, long frames = 0);

/// The closed form's time between flips, half its period [s] (rigid_free_rotation.hpp).
double closed_form_flip_interval(const RigidShape& shape, const RigidState& start);

/// A spin mostly about one principal axis: ω0 = 10 rad/s along it, 0.1 rad/s along the body axis
/// before it ((axis + 2) mod 3).
struct AxisSpin {
  int axis = 0;                  ///< body axis
  double moment = 0;             ///< its principal moment [kg·m²]
  RotationRun run;               ///< RK4 at 1 ms for 10 s
  double max_deviation_deg = 0;  ///< largest angle between ω and ±that axis [°]
  long flips_about_axis = 0;     ///< flips of that axis (FlipCounter)
};
/// The three spins, smallest moment first: only the intermediate one flips.
std::vector<AxisSpin> spins_about_axes(const RigidShape& shape, double t_end = 10.0);

/// One run of the trade: the error in R after T, and what it cost.
struct RotationTradePoint {
  long steps = 0;
  double h = 0;        ///< [s]
  double seconds = 0;  ///< wall time [s]
  double error = 0;    ///< ‖R − R_ref‖ (Frobenius) at T
};
/// Each integrator over `step_counts` steps of [0, t_end], against GSL's rk8pd at 1e-13.
struct RotationTrade {
  double t_end = 0;
  long reference_evaluations = 0;
  std::vector<std::pair<RotationIntegrator, std::vector<RotationTradePoint>>> curves;
};
RotationTrade rotation_trade(const RigidKernels& kernels, const std::vector<RotationIntegrator>& integrators,
                             const RigidShape& shape, const RigidState& start, double t_end,
                             const std::vector<long>& step_counts);

/// The flip times of the reference (GSL rk8pd at 1e-13) over [0, t_end] [s], sampled every
/// reference_sampling(start) seconds.
std::vector<double> reference_flip_times(const RigidShape& shape, const RigidState& start, double t_end);
/// min(1 ms, 0.05/|ω0|) [s]: at least 20 samples a radian turned, so no flip falls between two.
double reference_sampling(const RigidShape& shape, const RigidState& start);

/// One integrator at one step: does it still flip, and how often?
struct FlipSweepRow {
  RotationIntegrator integrator{};
  double h = 0;  ///< [s]
  long flips = 0;
  double interval = 0;          ///< mean time between flips [s] (NaN with fewer than two)
  double max_energy_drift = 0;  ///< |ΔE|/E
  bool diverged = false;
};
/// Each integrator at each step of `steps` [s] over [0, t_end].
std::vector<FlipSweepRow> flip_sweep(const RigidKernels& kernels,
                                     const std::vector<RotationIntegrator>& integrators,
                                     const RigidShape& shape, const RigidState& start, double t_end,
                                     const std::vector<double>& steps);

}  // namespace kit
