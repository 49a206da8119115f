#include <kit/rigid/rigid_stepper.hpp>

#include <array>

#include <kit/rigid/rigid_integrators.hpp>

namespace kit {
namespace {

struct IntegratorInfo {
  RotationIntegrator integrator;
  const char* flag;
  const char* display;
  const char* exercises;
};

constexpr std::array<IntegratorInfo, 6> integrator_table{{
    {RotationIntegrator::euler_matrix, "euler-R", "explicit Euler on R", "ex 8.3, 8.1"},
    {RotationIntegrator::euler_polar, "euler-R-polar", "Euler on R + polar", "ex 8.3, 8.1"},
    {RotationIntegrator::euler_quaternion, "euler-q", "Euler on q", "ex 8.3, 8.2"},
    {RotationIntegrator::exponential_map, "exp-map", "exponential map", "ex 8.3, 8.4"},
    {RotationIntegrator::midpoint, "midpoint", "implicit midpoint", ""},
    {RotationIntegrator::rk4, "rk4", "RK4 on (q, L_b)", ""},
}};

const IntegratorInfo& info(RotationIntegrator integrator) {
  return integrator_table[static_cast<std::size_t>(integrator)];
}

}  // namespace

const std::vector<RotationIntegrator>& rotation_integrators() {
  static const std::vector<RotationIntegrator> all = [] {
    std::vector<RotationIntegrator> v;
    for (const auto& entry : integrator_table) v.push_back(entry.integrator);
    return v;
  }();
  return all;
}

std::string flag_name(RotationIntegrator integrator) { return info(integrator).flag; }
std::string display_name(RotationIntegrator integrator) { return info(integrator).display; }
std::string exercises_of(RotationIntegrator integrator) { return info(integrator).exercises; }

std::optional<RotationIntegrator> rotation_integrator_named(const std::string& name) {
  for (const auto& entry : integrator_table)
    if (name == entry.flag) return entry.integrator;
  return std::nullopt;
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
