// What chapter 6's enumerations mean beyond their names (whose tables are in cloth.hpp and
// cloth_scene.hpp): the family a layout gives a kind of spring, and an integrator's stages. Kept
// apart from cloth.cpp and cloth_forces.cpp (the physics) so that the scene file and the flags
// need not link the force pass.
#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_scene.hpp>

namespace kit {

const std::optional<SpringFamily>& SpringLayout::family(SpringKind kind) const {
  switch (kind) {
    case SpringKind::structural:
      return structural;
    case SpringKind::shear:
      return shear;
    case SpringKind::bend:
      break;
  }
  return bend;
}

int stages(ClothIntegrator integrator) {
  switch (integrator) {
    case ClothIntegrator::explicit_euler:
    case ClothIntegrator::symplectic_euler:
      return 1;
    case ClothIntegrator::midpoint:
      return 2;
    case ClothIntegrator::rk4:
      return 4;
  }
  return 0;
}

}  // namespace kit
