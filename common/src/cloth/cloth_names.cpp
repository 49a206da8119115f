// The names of chapter 6's enumerations: spring families and explicit integrators. Kept apart
// from cloth.cpp and cloth_forces.cpp (the physics) so that the scene file and the flags can
// name things without the force pass.
#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_scene.hpp>

namespace kit {

const char* spring_kind_name(SpringKind kind) {
  switch (kind) {
    case SpringKind::structural: return "structural";
    case SpringKind::shear: return "shear";
    case SpringKind::bend: return "bend";
  }
  return "unknown";
}

const std::optional<SpringFamily>& SpringLayout::family(SpringKind kind) const {
  switch (kind) {
    case SpringKind::structural: return structural;
    case SpringKind::shear: return shear;
    case SpringKind::bend: break;
  }
  return bend;
}

const char* flag_name(ClothIntegrator integrator) {
  switch (integrator) {
    case ClothIntegrator::explicit_euler: return "explicit-euler";
    case ClothIntegrator::symplectic_euler: return "symplectic-euler";
    case ClothIntegrator::midpoint: return "midpoint";
    case ClothIntegrator::rk4: return "rk4";
  }
  return "unknown";
}

const char* display_name(ClothIntegrator integrator) {
  switch (integrator) {
    case ClothIntegrator::explicit_euler: return "explicit Euler";
    case ClothIntegrator::symplectic_euler: return "symplectic Euler";
    case ClothIntegrator::midpoint: return "midpoint (RK2)";
    case ClothIntegrator::rk4: return "classical RK4";
  }
  return "unknown";
}

int stages(ClothIntegrator integrator) {
  switch (integrator) {
    case ClothIntegrator::explicit_euler:
    case ClothIntegrator::symplectic_euler: return 1;
    case ClothIntegrator::midpoint: return 2;
    case ClothIntegrator::rk4: return 4;
  }
  return 0;
}

}  // namespace kit
