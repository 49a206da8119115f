#pragma once
// Chapter 8's "− collisions": a body dropped on the ground under gravity, bouncing by the
// impulses of rigid_contact.hpp, with its height and energy over time.
#include <vector>

#include <kit/rigid/rigid_contact.hpp>
#include <kit/rigid/rigid_stepper.hpp>

namespace kit {

/// Chapter 8's drops: from this height [m] (the lowest corner), flat and tilted by this angle [°].
inline constexpr double drop_height = 1.0, drop_tilt_deg = 30.0;

/// The body at rest, turned by `tilt_deg` [°] about z, its lowest corner `height` [m] above the ground.
RigidState dropped_state(const RigidShape& shape, double height, double tilt_deg);

/// About this many samples of a drop are kept, plus one at every bounce.
inline constexpr long max_drop_samples = 4000;

struct DropSample {
  double t = 0;              ///< [s]
  double centre_height = 0;  ///< y of the centre of mass [m]
  double lowest = 0;         ///< the lowest corner's y [m] (< 0: inside the ground)
  double kinetic = 0;        ///< [J]
  double potential = 0;      ///< M g y [J]
  double total() const { return kinetic + potential; }
};

struct DropRun {
  std::vector<DropSample> samples;  ///< every bounce, and max_drop_samples others evenly spaced
  std::vector<RigidState> frames;   ///< evenly spaced in time, for pictures and meshes
  std::vector<double> apexes;       ///< the centre's highest point after each bounce [m]
  int contacts = 0;                 ///< steps that ended in contact
  int bounces = 0;                  ///< of those, the ones that bounced
  double deepest = 0;               ///< deepest corner before a contact was resolved [m]
  double deepest_after = 0;         ///< deepest corner after it (≤ 0) [m]
  double friction_impulse = 0;      ///< Σ |f| over the run [N·s]
  double largest_gain = 0;          ///< the largest energy increase across one contact, lift included [J]
  int most_sweeps = 0;              ///< Gauss–Seidel sweeps of the hardest contact
  int unconverged_contacts = 0;     ///< contacts that used all max_contact_sweeps
  double largest_impulse_gain = 0;  ///< the largest kinetic energy the impulses added [J] (≤ 0: none)
  double largest_turn = 0;          ///< max ‖R − R(0)‖ (Frobenius) over the run: how far it turned
  /// The end of the last step at which the centre was more than flat_tolerance from its height
  /// lying flat [s]: flat and still from then on (t_end: not settled).
  double settled_at = 0;
  double diverged_at = -1;  ///< [s]; −1 if never
  RigidState end;
};

/// Drops the body from `start` for t_end [s] at step h: gravity contact.gravity along −y (P += h M g,
/// exact for x), the
/// rotation by `integrator`, then the ground contact. Keeps `frames` + 1 states evenly spaced in
/// time for output.
DropRun run_drop(const RigidKernels& kernels, RotationIntegrator integrator, const RigidShape& shape,
                 const RigidState& start, const GroundContact& contact, double h, double t_end, long frames);

/// The height of the centre when the body rests on the ground in the orientation R [m].
double resting_height(const RigidShape& shape, const Mat3& R);

/// How close to its flat resting height the centre must stay for the body to count as lying
/// flat [m]: rocking on an edge lifts the centre of the chapter's box by centimetres.
inline constexpr double flat_tolerance = 1e-4;

}  // namespace kit
