#include <kit/rigid/rigid_stepper.hpp>

#include <kit/rigid/rigid_integrators.hpp>

namespace kit {

std::string exercises_of(RotationIntegrator integrator) {
  switch (integrator) {
    case RotationIntegrator::euler_matrix:
    case RotationIntegrator::euler_polar:
      return "ex 8.3, 8.1";
    case RotationIntegrator::euler_quaternion:
      return "ex 8.3, 8.2";
    case RotationIntegrator::exponential_map:
      return "ex 8.3, 8.4";
    case RotationIntegrator::midpoint:
    case RotationIntegrator::rk4:
      break;
  }
  return "";
}

bool rotation_step(const RigidKernels& kernels, RotationIntegrator integrator, const RigidShape& shape,
                   RigidState& state, double h) {
  switch (integrator) {
    case RotationIntegrator::midpoint: {
      const bool whole = midpoint_rotation_substeps(shape, state, h);
      state.q = Quat(state.R);
      return whole;
    }
    case RotationIntegrator::rk4:
      rk4_rotation_step(shape, state, h);
      return true;
    default:
      break;
  }
  // The lecture's: ω = R I_body⁻¹ Rᵀ L (ex 8.3) at the start of the step, held over it.
  const Vec3 omega = kernels.angular_velocity(state.R, shape.inverse_inertia, state.L);
  switch (integrator) {
    case RotationIntegrator::euler_matrix:
      state.R = kernels.explicit_rotation_step(state.R, omega, h);
      return true;  // R is no rotation: q is left as it was, unused
    case RotationIntegrator::euler_polar:
      state.R = nearest_rotation(kernels.explicit_rotation_step(state.R, omega, h));
      state.q = Quat(state.R);
      return true;
    case RotationIntegrator::euler_quaternion:
      state.q = kernels.quaternion_step(state.q, omega, h);
      state.R = state.q.toRotationMatrix();
      return true;
    default:  // the exponential map
      state.R = kernels.exponential_map_step(state.R, omega, h);
      state.q = Quat(state.R);
      return true;
  }
}

Vec3 body_angular_velocity(const RigidShape& shape, const RigidState& state) {
  return shape.inverse_inertia * body_momentum(state);
}

}  // namespace kit
