#pragma once
// The lecture's "− collisions": a rigid body against the ground plane y = 0, by impulses. After a
// step, the corners of the body below the ground that still approach it are the contact; one
// impulse at their mean point r (from the centre of mass) gives the normal velocity there the
// value −e v_n (restitution e), and friction removes tangential velocity up to Coulomb's bound
// |J_t| ≤ μ J_n. With K(d) = 1/M + d · ((I⁻¹ (r × d)) × r), the inverse effective mass along d:
//   J_n = −(1 + e) v_n / K(n),   J_t = min(μ J_n, |v_t| / K(t)),   P += J,  L += r × J.
// The body is then lifted out of the ground: by the depth, plus e times it when it bounces, as if
// it had turned back at the ground instead of at the bottom of the step (the energy stays right to
// O(g h²) per bounce).
#include <kit/rigid_body.hpp>

namespace kit {

struct GroundContact {
  double restitution = 0.5;    ///< e in [0, 1]: the normal speed kept, as a fraction
  double friction = 0.3;       ///< μ ≥ 0, Coulomb
  double resting_speed = 0.05; ///< [m/s] below this approach speed a contact does not bounce (e = 0),
                               ///< so that a body at rest does not chatter
};

/// What one contact did.
struct ContactEvent {
  int points = 0;          ///< corners below the ground
  double depth = 0;        ///< how far below the lowest one was [m]
  double normal_impulse = 0;  ///< J_n [N·s]
  double friction_impulse = 0;  ///< |J_t| [N·s]
};

/// The lowest point of the body, min over its corners of (x + R c).y [m].
double lowest_point(const RigidShape& shape, const RigidState& state);

/// Resolves the body against the ground y = 0, as above. Returns what happened (points = 0: no contact).
ContactEvent resolve_ground_contact(const RigidShape& shape, RigidState& state, const GroundContact& contact);

}  // namespace kit
