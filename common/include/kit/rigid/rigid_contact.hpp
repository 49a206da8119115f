#pragma once
// The lecture's "− collisions": a rigid body against the ground plane y = 0, by impulses. After a
// step, the corners below the ground are the contact. Every corner i gets its own normal impulse
// λ_i ≥ 0 and friction impulse f_i with |f_i| ≤ μ λ_i (Coulomb), all solved together by projected
// Gauss–Seidel on the accumulated impulses: one corner's impulse changes the others' velocities
// through the body's rotation, so a box landing on an edge and tipping flat is stopped at each
// corner, not at their mean point. At corner i (arm r_i from the centre of mass), with
//   K_i(d) = 1/M + d · ((I⁻¹ (r_i × d)) × r_i)   the inverse effective mass along d,
// a sweep sets λ_i ← max(0, λ_i + (v_target − v_n)/K_i(n)), then clamps the friction, until no
// impulse changes by more than 1e-14 of the largest (at 1e-12, a flat drop turned by 1e-11 rad).
// Then P += Σ J_i and L += Σ r_i × J_i.
// One decision per contact: it bounces (v_target = −e v_n,i at every corner) when the deepest
// corner arrives faster than the resting speed, else it rests (v_target = 0), so that a flat box
// neither turns nor chatters. The body is then lifted out of the ground by the depth, plus e times
// it when it bounces, as if it had turned back at the ground instead of at the bottom of the
// step. That lift is a position fix, not a force: when a corner sank by turning while the centre
// did not fall, it adds up to M g (1 + e) × depth of energy (at most 1.6e-4 J in chapter 8's drops).
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// Standard gravity [m/s²], pulling along −y.
inline constexpr double standard_gravity = 9.81;

struct GroundContact {
  double restitution = 0.5;           ///< e in [0, 1]: the normal speed kept, as a fraction
  double friction = 0.3;              ///< μ ≥ 0, Coulomb
  double resting_speed = 0.05;        ///< [m/s] below this approach speed a contact does not bounce (e = 0),
                                      ///< so that a body at rest does not chatter
  double gravity = standard_gravity;  ///< g [m/s²] pulling the body along −y
};

/// What one contact did.
struct ContactEvent {
  int points = 0;               ///< corners below the ground
  double depth = 0;             ///< how far below the lowest one was [m]
  double normal_impulse = 0;    ///< Σ λ_i [N·s]
  double friction_impulse = 0;  ///< |Σ f_i| [N·s]: the net friction (corners' can cancel)
  bool bounced = false;         ///< restitution applied (else the contact rests)
  int sweeps = 0;               ///< Gauss–Seidel sweeps taken (max_contact_sweeps: not converged)
  double kinetic_change = 0;    ///< kinetic energy after the impulses − before, the lift apart [J]
};

/// The lowest point of the body, min over its corners of (x + R c).y [m].
double lowest_point(const RigidShape& shape, const RigidState& state);

/// Resolves the body against the ground y = 0, as above. Returns what happened (points = 0: no contact).
ContactEvent resolve_ground_contact(const RigidShape& shape, RigidState& state, const GroundContact& contact);

/// At most this many Gauss–Seidel sweeps: a box's corners resting flat converge in about 30; a
/// box rocking on an edge, whose corners' restitution targets conflict, can take them all.
inline constexpr int max_contact_sweeps = 200;

}  // namespace kit
