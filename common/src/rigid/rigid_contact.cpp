#include <kit/rigid/rigid_contact.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace kit {
namespace {

// One corner in contact: its arm from the centre of mass [m], the normal speed it arrived with
// [m/s], and its accumulated impulses [N·s].
struct CornerContact {
  Vec3 arm;
  double arrival = 0;
  double normal = 0;
  Vec3 friction = Vec3::Zero();
};

// The body's velocities as the impulses change them: v [m/s] and ω [rad/s], both world.
class BodyVelocity {
 public:
  BodyVelocity(const RigidShape& shape, const RigidState& state)
      : shape_(shape), R_(state.R), P_(state.P), L_(state.L) {}
  Vec3 at(const Vec3& arm) const { return P_ / shape_.mass + omega().cross(arm); }
  void apply(const Vec3& arm, const Vec3& impulse) {
    P_ += impulse;
    L_ += arm.cross(impulse);
  }
  // K(d): the velocity change along d at `arm` per unit impulse along d [1/kg].
  double inverse_effective_mass(const Vec3& arm, const Vec3& d) const {
    return 1.0 / shape_.mass + d.dot(world_inverse_inertia(arm.cross(d)).cross(arm));
  }
  void store(RigidState& state) const {
    state.P = P_;
    state.L = L_;
  }

 private:
  Vec3 world_inverse_inertia(const Vec3& v) const {
    return R_ * (shape_.inverse_inertia * (R_.transpose() * v));
  }
  Vec3 omega() const { return world_inverse_inertia(L_); }
  const RigidShape& shape_;
  Mat3 R_;
  Vec3 P_, L_;
};

// One sweep over the corners; returns the largest change of an impulse [N·s].
double sweep(std::vector<CornerContact>& corners, BodyVelocity& body, double restitution, double friction) {
  const Vec3 up = Vec3::UnitY();
  double largest = 0;
  for (CornerContact& c : corners) {
    const double target = c.arrival < 0 ? -restitution * c.arrival : 0.0;
    const double speed = body.at(c.arm).dot(up);
    const double normal = std::max(0.0, c.normal + (target - speed) / body.inverse_effective_mass(c.arm, up));
    body.apply(c.arm, (normal - c.normal) * up);
    largest = std::max(largest, std::abs(normal - c.normal));
    c.normal = normal;
    // Friction: cancel the sliding velocity, within Coulomb's disc of radius μ λ_i.
    const Vec3 velocity = body.at(c.arm);
    const Vec3 sliding = velocity - velocity.dot(up) * up;
    Vec3 wanted = c.friction;
    if (sliding.norm() > 0) wanted -= sliding / body.inverse_effective_mass(c.arm, sliding.normalized());
    const double bound = friction * c.normal;
    if (wanted.norm() > bound) wanted *= bound / wanted.norm();
    body.apply(c.arm, wanted - c.friction);
    largest = std::max(largest, (wanted - c.friction).norm());
    c.friction = wanted;
  }
  return largest;
}

}  // namespace

double lowest_point(const RigidShape& shape, const RigidState& state) {
  double lowest = HUGE_VAL;
  for (const Vec3& corner : shape.corners) lowest = std::min(lowest, (state.x + state.R * corner).y());
  return lowest;
}

ContactEvent resolve_ground_contact(const RigidShape& shape, RigidState& state,
                                    const GroundContact& contact) {
  ContactEvent event;
  BodyVelocity body(shape, state);
  std::vector<CornerContact> corners;
  double deepest_arrival = 0;
  for (const Vec3& corner : shape.corners) {
    const Vec3 arm = state.R * corner;
    const double height = (state.x + arm).y();
    if (height >= 0) continue;
    const double arrival = body.at(arm).y();
    if (-height > event.depth) event.depth = -height, deepest_arrival = arrival;
    corners.push_back({arm, arrival});
  }
  event.points = int(corners.size());
  if (corners.empty()) return event;
  event.bounced = -deepest_arrival >= contact.resting_speed && contact.restitution > 0;
  const double e = event.bounced ? contact.restitution : 0.0;
  double scale = 0;  // the impulse that would stop the body's fastest corner [N·s]
  for (const auto& c : corners) scale = std::max(scale, std::abs(c.arrival) * shape.mass);
  do {
    ++event.sweeps;
  } while (sweep(corners, body, e, contact.friction) > 1e-14 * scale && event.sweeps < max_contact_sweeps);
  const double kinetic_before = kinetic_energy(shape, state);
  body.store(state);
  event.kinetic_change = kinetic_energy(shape, state) - kinetic_before;
  Vec3 friction = Vec3::Zero();
  for (const auto& c : corners) {
    event.normal_impulse += c.normal;
    friction += c.friction;
  }
  event.friction_impulse = friction.norm();
  state.x.y() += (1 + e) * event.depth;
  return event;
}

}  // namespace kit
