#pragma once
// What a cloth scene is (chapters 6 and 7): the sheet, its springs, the forces that act, the
// pins, the colliders and how to run it. A scene file (cloth_scene_file.hpp) fills these in and
// lists only what the scene models: an absent spring family, force or collider is never built.
#include <optional>
#include <string>
#include <vector>

#include <kit/base/enum_names.hpp>
#include <kit/cloth/cloth.hpp>
#include <kit/render/camera.hpp>

namespace kit {

/// A node held still: grid coordinates (i, j); negative values count from the far end (−1 is
/// the last column or row), so a pin stays at its corner when the resolution changes.
struct Pin {
  int i = 0, j = 0;
};

/// A fixed, frictional sphere the cloth cannot enter.
struct SphereCollider {
  Vec3 center{0, 0, 0};  ///< [m]
  double radius = 1;     ///< [m], > 0
  double friction = 0;   ///< Coulomb coefficient μ ≥ 0 (tangential Δv ≤ μ × normal Δv)
};

/// The ground: the half-space y < height is solid.
struct GroundCollider {
  double height = 0;    ///< [m]
  double friction = 0;  ///< Coulomb coefficient μ ≥ 0
};

/// Provot 1995: after each step, springs stretched beyond (1 + max_strain)·L0 are pulled back,
/// a few passes over the structural and shear springs.
struct StrainLimit {
  double max_strain = 0.1;  ///< relative, > 0
  int iterations = 4;       ///< passes per step, ≥ 1
};

/// The explicit integrators of chapter 6.
enum class ClothIntegrator { explicit_euler, symplectic_euler, midpoint, rk4 };
/// Their names in --integrator, scene files ([run] integrator) and summaries, and in figures.
inline constexpr auto cloth_integrator_names = enum_names<ClothIntegrator>({
    {ClothIntegrator::explicit_euler, "explicit-euler", "explicit Euler"},
    {ClothIntegrator::symplectic_euler, "symplectic-euler", "symplectic Euler"},
    {ClothIntegrator::midpoint, "midpoint", "midpoint (RK2)"},
    {ClothIntegrator::rk4, "rk4", "classical RK4"},
});
static_assert(cloth_integrator_names.in_order());
inline constexpr auto all_cloth_integrators = cloth_integrator_names.all();
inline const char* flag_name(ClothIntegrator integrator) { return cloth_integrator_names.flag(integrator); }
inline const char* display_name(ClothIntegrator integrator) {
  return cloth_integrator_names.display(integrator);
}
int stages(ClothIntegrator integrator);  ///< force evaluations per step

struct ClothScene {
  std::string name;
  std::string description;
  ClothGrid grid;
  SpringLayout springs;
  std::optional<Vec3> gravity;  ///< [m/s²]; absent: no gravity force is computed
  std::optional<double> drag;   ///< linear air drag [1/s]: f = −m·drag·v; absent: none
  std::vector<Pin> pins;
  std::vector<SphereCollider> spheres;
  std::optional<GroundCollider> ground;
  std::optional<StrainLimit> strain_limit;
  Camera camera{{0, 1, 3}, {0, 0.5, 0}, 40};  ///< where the rendered frames look from
  // How the scene runs by default (flags override).
  ClothIntegrator integrator = ClothIntegrator::symplectic_euler;
  double dt = 1e-4;  ///< [s]
  double t_end = 2;  ///< [s]
  int frames = 60;   ///< frames written over [0, t_end]
};

/// The scene at another resolution: nx = n nodes across, ny chosen so that cells stay as close
/// to square as the sheet allows (at least 2). Pins keep their meaning (negative = from the end).
ClothScene at_resolution(const ClothScene& scene, int n);

/// The scene with n nodes along its longer side and cells as close to square as the shorter
/// allows (at least 2): at most n² nodes whatever the sheet's proportions (the chapter's
/// stability experiments). UsageError when a pin falls outside.
ClothScene at_longest_side(const ClothScene& scene, int n);

/// Node index of a pin on the scene's grid.
long pinned_node(const ClothGrid& grid, const Pin& pin);

}  // namespace kit
