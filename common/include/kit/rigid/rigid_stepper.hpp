#pragma once
// Chapter 8's six ways to turn a rigid body over one step, side by side. Four are the lecture's
// and the students' (ex 8.1 to 8.4, reached through RigidKernels); two are the kit's
// (rigid_integrators.hpp). Every one reads ω from L the same way, so what differs is only how
// the orientation moves:
//   euler-R        R += h ω* R, the lecture's ODE as written: R leaves the rotations;
//   euler-R-polar  the same, then R ← its nearest rotation (polar factor): back on SO(3);
//   euler-q        q += h/2 (0, ω) ⊗ q, then q/|q|: a rotation always, first order;
//   exp-map        R ← exp(h ω*) R (Rodrigues): a rotation always, first order (ω frozen);
//   midpoint       the implicit midpoint on L_b: E, |L| and RᵀR = 1 to round-off, second order
//                  (a step whose fixed point stalls is split into halves);
//   rk4            classical RK4 on (q, L_b): fourth order, E and |L| drift at O(h⁴).
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <kit/base/enum_names.hpp>
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// The lecture's steps, as a student writes them (solutions/rigid_*.hpp).
struct RigidKernels {
  /// ex 8.1: R + h ω* R, ω [rad/s] in the world frame, h [s].
  Mat3 (*explicit_rotation_step)(const Mat3& R, const Vec3& omega, double h) = nullptr;
  /// ex 8.2: q + h/2 (0, ω) ⊗ q, renormalised.
  Quat (*quaternion_step)(const Quat& q, const Vec3& omega, double h) = nullptr;
  /// ex 8.3: ω = R I_body⁻¹ Rᵀ L [rad/s].
  Vec3 (*angular_velocity)(const Mat3& R, const Mat3& inverse_inertia_body, const Vec3& L) = nullptr;
  /// ex 8.4: exp(h ω*) R.
  Mat3 (*exponential_map_step)(const Mat3& R, const Vec3& omega, double h) = nullptr;
};

enum class RotationIntegrator { euler_matrix, euler_polar, euler_quaternion, exponential_map, midpoint, rk4 };
/// The --integrator values, and what tables and legends call them.
inline constexpr auto rotation_integrator_names = enum_names<RotationIntegrator>({
    {RotationIntegrator::euler_matrix, "euler-R", "explicit Euler on R"},
    {RotationIntegrator::euler_polar, "euler-R-polar", "Euler on R + polar"},
    {RotationIntegrator::euler_quaternion, "euler-q", "Euler on q"},
    {RotationIntegrator::exponential_map, "exp-map", "exponential map"},
    {RotationIntegrator::midpoint, "midpoint", "implicit midpoint"},
    {RotationIntegrator::rk4, "rk4", "RK4 on (q, L_b)"},
});
static_assert(rotation_integrator_names.in_order());

/// All six, in the order above (the lecture's first).
inline constexpr auto rotation_integrators = rotation_integrator_names.all();
inline std::string flag_name(RotationIntegrator integrator) {
  return rotation_integrator_names.flag(integrator);
}
inline std::string display_name(RotationIntegrator integrator) {
  return rotation_integrator_names.display(integrator);
}
/// The exercises it runs ("ex 8.3, 8.1"), or "" for the kit's own.
std::string exercises_of(RotationIntegrator integrator);

/// Turns `state` (R, and q for the quaternion integrators; L as it is) over h [s] without
/// torque; x and P are left alone. The kit's integrators keep R and q in step; the lecture's
/// keep the one they step and set the other from it when it is a rotation. Returns false when
/// the midpoint's fixed point stalled and the step was split (midpoint_rotation_substeps).
/// Throws NotImplemented when a kernel it needs is a student's placeholder.
bool rotation_step(const RigidKernels& kernels, RotationIntegrator integrator, const RigidShape& shape,
                   RigidState& state, double h);

/// The step at which frame j of `frames` frames over `steps` steps is taken, round(j steps /
/// frames): frames evenly spaced over the whole run.
inline long frame_step(long j, long steps, long frames) {
  return std::lround(double(j) * double(steps) / double(frames));
}

/// ω in the body frame, I_body⁻¹ Rᵀ L [rad/s]: what the flips are seen in.
Vec3 body_angular_velocity(const RigidShape& shape, const RigidState& state);

}  // namespace kit
