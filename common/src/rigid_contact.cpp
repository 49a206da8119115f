#include <kit/rigid_contact.hpp>

#include <algorithm>
#include <cmath>

namespace kit {
namespace {

// The world's inverse inertia R I⁻¹ Rᵀ applied to a vector [1/(kg·m²)] times its units.
Vec3 apply_world_inverse_inertia(const RigidShape& shape, const Mat3& R, const Vec3& v) {
  return R * (shape.inverse_inertia * (R.transpose() * v));
}

// K(d) = 1/M + d · ((I⁻¹ (r × d)) × r): the velocity change along d at r per unit impulse along d.
double inverse_effective_mass(const RigidShape& shape, const Mat3& R, const Vec3& r, const Vec3& d) {
  return 1.0 / shape.mass + d.dot(apply_world_inverse_inertia(shape, R, r.cross(d)).cross(r));
}

}  // namespace

double lowest_point(const RigidShape& shape, const RigidState& state) {
  double lowest = HUGE_VAL;
  for (const Vec3& corner : shape.corners) lowest = std::min(lowest, (state.x + state.R * corner).y());
  return lowest;
}

ContactEvent resolve_ground_contact(const RigidShape& shape, RigidState& state, const GroundContact& contact) {
  ContactEvent event;
  const Vec3 up = Vec3::UnitY();
  const Vec3 velocity = state.P / shape.mass;
  const Vec3 omega = apply_world_inverse_inertia(shape, state.R, state.L);
  Vec3 arm_sum = Vec3::Zero();
  int approaching = 0;
  for (const Vec3& corner : shape.corners) {
    const Vec3 arm = state.R * corner;
    const double height = (state.x + arm).y();
    if (height >= 0) continue;
    ++event.points;
    event.depth = std::max(event.depth, -height);
    if ((velocity + omega.cross(arm)).dot(up) < 0) arm_sum += arm, ++approaching;
  }
  if (event.points == 0) return event;
  bool bounced = false;
  if (approaching > 0) {
    const Vec3 arm = arm_sum / approaching;
    const Vec3 relative = velocity + omega.cross(arm);
    const double normal_speed = relative.dot(up);
    if (normal_speed < 0) {
      const double e = -normal_speed < contact.resting_speed ? 0.0 : contact.restitution;
      bounced = e > 0;
      event.normal_impulse = -(1 + e) * normal_speed / inverse_effective_mass(shape, state.R, arm, up);
      Vec3 impulse = event.normal_impulse * up;
      const Vec3 sliding = relative - normal_speed * up;
      if (sliding.norm() > 0 && contact.friction > 0) {
        const Vec3 along = sliding.normalized();
        event.friction_impulse = std::min(contact.friction * event.normal_impulse,
                                          sliding.norm() / inverse_effective_mass(shape, state.R, arm, along));
        impulse -= event.friction_impulse * along;
      }
      state.P += impulse;
      state.L += arm.cross(impulse);
    }
  }
  state.x.y() += (bounced ? 1 + contact.restitution : 1.0) * event.depth;
  return event;
}

}  // namespace kit
