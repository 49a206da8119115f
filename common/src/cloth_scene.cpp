// placeholder until the scene-file branch lands
#include <kit/cloth_scene.hpp>
namespace kit {
long pinned_node(const ClothGrid& grid, const Pin& pin) {
  return grid.index(pin.i < 0 ? grid.nx + pin.i : pin.i, pin.j < 0 ? grid.ny + pin.j : pin.j);
}
const char* flag_name(ClothIntegrator i) {
  switch (i) { case ClothIntegrator::explicit_euler: return "explicit-euler"; case ClothIntegrator::symplectic_euler: return "symplectic-euler"; case ClothIntegrator::midpoint: return "midpoint"; case ClothIntegrator::rk4: return "rk4"; }
  return "";
}
const char* display_name(ClothIntegrator i) {
  switch (i) { case ClothIntegrator::explicit_euler: return "explicit Euler"; case ClothIntegrator::symplectic_euler: return "symplectic Euler"; case ClothIntegrator::midpoint: return "midpoint RK2"; case ClothIntegrator::rk4: return "RK4"; }
  return "";
}
const std::optional<SpringFamily>& SpringLayout::family(SpringKind kind) const {
  return kind == SpringKind::structural ? structural : kind == SpringKind::shear ? shear : bend;
}
}
