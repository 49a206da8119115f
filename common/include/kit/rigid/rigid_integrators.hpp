#pragma once
// The kit's own rigid-body steps, beside the lecture's (the exercises of chapter 8). They work in
// the body frame, where the torque-free rotation is Euler's equations
//   L_b' = L_b × ω_b,  ω_b = I_body⁻¹ L_b,  R' = R ω_b*,  L = R L_b constant in the world,
// and torques, when there are any, are kicks L += h τ given by the caller (contact impulses).
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// Euler's equations of the torque-free body: L_b' = L_b × ω_b, ω_b = I⁻¹ L_b [kg·m²/s²].
Vec3 euler_equations(const RigidShape& shape, const Vec3& body_momentum);
/// The quaternion's rate q' = ½ q ⊗ (0, ω_b), q = (w, x, y, z): the body-frame angular
/// velocity [rad/s] turns the orientation from the right.
Eigen::Vector4d quaternion_rate(const Eigen::Vector4d& q, const Vec3& omega_body);

/// x and P over h [s] under a force F [N] constant over the step (gravity): P += h F,
/// x += h P/M + h²/2 F/M, exact for a constant force.
void translation_step(const RigidShape& shape, RigidState& state, double h, const Vec3& force);

/// The Cayley map of the rotation vector r [rad]: (1 − r*/2)⁻¹ (1 + r*/2), a rotation exactly, close
/// to exp(r*) to third order; r* is the cross-product matrix of r.
Mat3 cayley(const Vec3& r);

/// The most fixed-point iterations of one midpoint step: reaching it means the iteration stalled.
inline constexpr int midpoint_max_iterations = 100;

/// The implicit midpoint rule on L_b, solved by fixed-point iteration to round-off, a
/// Lie–Poisson integrator: with ω_m = I⁻¹ (L_b + L_b⁺)/2 it is exactly L_b⁺ = cay(h ω_m)ᵀ L_b
/// and R⁺ = R cay(h ω_m). Hence R stays a rotation, L = R L_b is unchanged, and the energy
/// ½ L_bᵀ I⁻¹ L_b (a quadratic invariant, which the midpoint rule keeps) is conserved: all three
/// to round-off, as long as the iteration converges. It contracts at a rate of about
/// h|ω|(I3 − I1)/I2, so it stalls from about h|ω| ~ 1. Returns the iterations taken (at most
/// midpoint_max_iterations).
int midpoint_rotation_step(const RigidShape& shape, RigidState& state, double h);

/// The midpoint step over h, split into halves (recursively, down to h/2¹⁶) where the fixed point
/// stalls: every piece keeps E, |L| and RᵀR = 1, so the whole step does too, at any h. Returns
/// false when it had to split (the step cost more than one solve).
bool midpoint_rotation_substeps(const RigidShape& shape, RigidState& state, double h, int depth = 0);

/// Classical RK4 on (q, L_b): q' = ½ q ⊗ (0, ω_b), L_b' = L_b × ω_b; q renormalised after the
/// step, R = R(q), L = R L_b. Fourth order; neither the energy nor |L| is conserved exactly.
void rk4_rotation_step(const RigidShape& shape, RigidState& state, double h);

}  // namespace kit
