#pragma once
// Chapter 8's model: a rigid body (lecture, "Mécanique du solide"). Every point shares the same
// parameters, so the state is four vectors and matrices:
//   x [m] the centre of mass, R the orientation (body → world), P = M v [kg·m/s] the linear
//   momentum and L = I(t) ω [kg·m²/s] the angular momentum, both in the world frame;
//   d/dt (x, R, P, L) = (v, ω* R, F, τ), with v = P/M, I(t) = R I_body Rᵀ, and ω* the
//   cross-product matrix of ω (ω* a = ω × a: errata 15, the lecture's "*").
// Here: the shapes and their mass properties, the state, and what the chapter measures on it.
// The lecture's steps (ω from L, the explicit step on R, the quaternion step, the exponential
// map) are exercises (solutions/rigid_*.hpp).
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <kit/base/vec3.hpp>

namespace kit {

using Quat = Eigen::Quaterniond;

/// A solid box of the body, in the body frame: its centre [m] and its full side lengths [m].
struct BoxPart {
  Vec3 centre = Vec3::Zero();
  Vec3 sides = Vec3::Ones();
};

/// What a body is made of: its mass, its inertia about its centre of mass in the body frame, and
/// its geometry (boxes, for drawing and for contact with the ground).
struct RigidShape {
  std::string name;                         ///< "box", "cylinder", "t-handle"
  double mass = 1.0;                        ///< M [kg]
  Mat3 inertia = Mat3::Identity();          ///< I_body [kg·m²], about the centre of mass, body axes
  Mat3 inverse_inertia = Mat3::Identity();  ///< I_body⁻¹ [1/(kg·m²)]
  std::vector<BoxPart> parts;               ///< the solid, centred on the centre of mass
  std::vector<Vec3> corners;                ///< points of the surface that can touch the ground [m]

  /// The principal moments I1 ≤ I2 ≤ I3 [kg·m²].
  Vec3 principal_moments() const;
};

/// A solid box of mass M [kg] and sides a, b, c [m] along x, y, z:
/// I = M/12 diag(b² + c², a² + c², a² + b²).
RigidShape box_shape(double mass, const Vec3& sides);
/// A solid cylinder of mass M [kg], radius r and height h [m], its axis along y:
/// I_y = M r²/2, I_x = I_z = M (3 r² + h²)/12. Collided as its 16-sided prism, drawn as its
/// bounding box (its one part).
RigidShape cylinder_shape(double mass, double radius, double height);
/// The T-handle of the Dzhanibekov effect: a bar 30 × 4 × 4 cm along x and a stem 4 × 30 × 4 cm
/// along −y from the bar's middle, of one density, mass M [kg] in all. Its principal axes are
/// the body axes and its moments distinct, about 0.0040 M (y, along the stem), 0.011 M (x, along
/// the bar: the intermediate axis) and 0.015 M (z) [kg·m²].
RigidShape t_handle_shape(double mass);

/// The names --body takes: "t-handle", "box", "cylinder".
std::vector<std::string> shape_names();
/// The shape of one of those names (std::invalid_argument otherwise).
RigidShape shape_named(const std::string& name);

/// The state of the lecture: x, R, P, L; `q` is the orientation as a unit quaternion, kept by the
/// integrators that step it (R is then q's matrix).
struct RigidState {
  Vec3 x = Vec3::Zero();      ///< centre of mass [m], world
  Mat3 R = Mat3::Identity();  ///< orientation, body → world
  Quat q = Quat::Identity();  ///< the same orientation, for quaternion integrators
  Vec3 P = Vec3::Zero();      ///< linear momentum [kg·m/s], world
  Vec3 L = Vec3::Zero();      ///< angular momentum [kg·m²/s], world
};

/// A body at rest at `x` turning at ω_body [rad/s] about its own axes: R = I, L = I_body ω.
RigidState spinning_state(const RigidShape& shape, const Vec3& x, const Vec3& omega_body);

/// The angular momentum in the body frame, Rᵀ L [kg·m²/s]. With an R that has drifted off the
/// rotations (explicit Euler on R) this is what the lecture's ω = R I⁻¹ Rᵀ L reads.
Vec3 body_momentum(const RigidState& state);
/// Kinetic energy P²/(2M) + ½ (RᵀL)ᵀ I_body⁻¹ (RᵀL) [J]: its rotational part is ½ ω·L.
double kinetic_energy(const RigidShape& shape, const RigidState& state);
/// Rotational kinetic energy ½ (RᵀL)ᵀ I_body⁻¹ (RᵀL) [J].
double rotational_energy(const RigidShape& shape, const RigidState& state);
/// ‖RᵀR − I‖ (Frobenius): 0 for a rotation; how far an integrator has left SO(3).
double orthonormality_error(const Mat3& R);
/// The rotation nearest R (the polar factor U Vᵀ of R = U Σ Vᵀ, with det = +1): what
/// re-orthonormalising after a step restores.
Mat3 nearest_rotation(const Mat3& R);

}  // namespace kit
