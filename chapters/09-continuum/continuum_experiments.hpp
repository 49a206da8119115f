#pragma once
// Chapter 9's experiments (lecture, "Mécanique des milieux continus"), each on FemBody:
//   the cantilever under its own weight against Euler–Bernoulli, by mesh and by model and solver;
//   one element turned rigidly, where the small strain sees strain and ghost forces;
//   a spinning plate, which the linear model distorts and St Venant–Kirchhoff does not;
//   a stretched sheet on regular and irregular meshes: the springs' mesh dependence.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <kit/base/enum_names.hpp>
#include <kit/fem/fem_body.hpp>
#include <kit/fem/fem_integrators.hpp>
#include <kit/fem/fem_statics.hpp>
#include <kit/ode/richardson.hpp>

namespace kit {

// --- the cantilever --------------------------------------------------------------------------
/// A beam 1 m long and 0.1 m high, clamped at x = 0 (every node there pinned), under gravity
/// along −y, in plane stress; meshed by 10 ny × ny cells with alternating diagonals.
inline constexpr double cantilever_length = 1.0, cantilever_height = 0.1;
/// Euler–Bernoulli's tip deflection q L⁴ / (8 E I) [m] for q = ρ g h t, I = t h³ / 12.
double euler_bernoulli_tip(const FemMaterial& material, double gravity = 9.81);
/// Timoshenko's tip deflection of the same beam [m], shear included (κ = 5/6, G = E / (2 (1 + ν))).
double timoshenko_tip(const FemMaterial& material, double gravity = 9.81);
/// Its first bending frequency ω1 = 1.8751² √(E I / (ρ A L⁴)) [rad/s], which sets the damping
/// and the time the dynamic solvers need to come to rest.
double cantilever_first_frequency(const FemMaterial& material);

/// How the cantilever's rest state is found.
enum class TipSolver {
  newton,               ///< static: Newton's method with a direct solver (solve_static)
  explicit_relaxation,  ///< symplectic Euler at 0.9 of the step limit, damped at c = 2ω1, for 20/ω1
  implicit_relaxation,  ///< implicit Euler, 60 steps of 1/(2ω1) with the same damping, PCG (ex 7.3)
};
inline constexpr auto tip_solver_names = enum_names<TipSolver>({
    {TipSolver::newton, "newton", "static Newton"},
    {TipSolver::explicit_relaxation, "explicit-relaxation", "explicit relaxation"},
    {TipSolver::implicit_relaxation, "implicit-relaxation", "implicit relaxation"},
});
static_assert(tip_solver_names.in_order());
inline const char* solver_name(TipSolver solver) { return tip_solver_names.display(solver); }

struct TipRun {
  FemModel model = FemModel::stvk;
  TipSolver solver = TipSolver::newton;
  int ny = 0;
  long elements = 0;
  double tip = 0;       ///< the free end's mean downward displacement [m]
  double error = 0;     ///< tip / Euler–Bernoulli − 1
  double seconds = 0;   ///< wall time of the solve [s]
  long steps = 0;       ///< Newton steps or time steps
  long iterations = 0;  ///< the implicit steps' PCG iterations, summed
  bool done = false;    ///< converged (newton) or came to rest without diverging (relaxation)
  std::string failure;
};
/// The cantilever with ny cells through its height. A relaxation that would need more than
/// `step_budget` steps is not run: it is returned with done = false and the steps it would take.
TipRun run_cantilever(const FemMaterial& material, FemModel model, TipSolver solver, int ny,
                      const ContinuumKernels& kernels, long step_budget = 200000);

/// The cantilever by Newton at ny = 1, 2, 4, … `finest` cells through its height: Richardson's
/// limit from the three finest meshes (the 2-D answer, which is not Euler–Bernoulli's: the beam
/// shears too), and the order p of the discretisation error |tip − limit| ∝ ny^−p (the cell size
/// to the power p), fitted by least squares from ny = 2 to the next-to-finest mesh.
struct TipConvergence {
  std::vector<TipRun> runs;
  Convergence richardson;
  double order = 0;
};
TipConvergence cantilever_convergence(const FemMaterial& material, FemModel model,
                                      const ContinuumKernels& kernels, int finest = 32);

// --- a rigid turn ----------------------------------------------------------------------------
/// One element (the right triangle (0, 0), (0.1, 0), (0, 0.1) m) turned rigidly by `degrees` in
/// its plane: its strains and the largest nodal force of each model, the forces relative to
/// those of a 1% stretch of the same element.
struct TurnedElement {
  double degrees = 0;
  double cauchy_strain = 0;  ///< |ε| (Frobenius)
  double green_strain = 0;   ///< |E|
  double linear_force = 0;   ///< relative to the 1% stretch's
  double stvk_force = 0;
};
std::vector<TurnedElement> turn_sweep(const FemMaterial& material, const ContinuumKernels& kernels,
                                      int samples = 37);

// --- the spinning plate ----------------------------------------------------------------------
inline constexpr double plate_side = 0.5;                     ///< [m]
inline constexpr double plate_spin = 3.14159265358979323846;  ///< ω [rad/s]: half a turn a second
enum class MeshKind { regular, irregular };
/// Their names in --mesh and summaries.
inline constexpr auto mesh_kind_names = enum_names<MeshKind>({
    {MeshKind::regular, "regular", "regular"},
    {MeshKind::irregular, "irregular", "irregular"},
});
static_assert(mesh_kind_names.in_order());
inline const char* mesh_name(MeshKind kind) { return mesh_kind_names.flag(kind); }
/// The rectangle [0, width] × [0, height] in n_x × n_y cells: alternating diagonals, or the
/// irregular mesh of the same boundary nodes (seed 9).
TriangleMesh continuum_mesh(double width, double height, int nx, int ny, MeshKind kind);

enum class TimeIntegrator { explicit_euler, implicit_euler };
/// Their names in --integrator and summaries.
inline constexpr auto time_integrator_names = enum_names<TimeIntegrator>({
    {TimeIntegrator::explicit_euler, "explicit", "explicit (symplectic Euler)"},
    {TimeIntegrator::implicit_euler, "implicit", "implicit Euler"},
});
static_assert(time_integrator_names.in_order());
inline const char* integrator_name(TimeIntegrator integrator) {
  return time_integrator_names.flag(integrator);
}
struct PlateSample {
  double t = 0;       ///< [s]
  double strain = 0;  ///< the largest Green strain of the current shape, whatever the model
  double angle = 0;   ///< how far the plate has turned, from its first edge [rad]
  double energy = 0;  ///< kinetic + the model's elastic energy [J]
};
struct PlateRun {
  std::vector<PlateSample> samples;
  long steps = 0, iterations = 0;
  bool diverged = false;   ///< a position stopped being finite, or the energy grew a hundredfold
  double diverged_at = 0;  ///< when that was seen [s] (checked at every sample)
  double h = 0;
};
/// The plate, free, spinning at plate_spin about its centre, for t_end [s] at step h [s] (0: the
/// integrator's default, 0.9 of the explicit limit or 1 ms), sampled `samples` times (at most
/// once a step) after the start. `on_sample` sees the body at each sample, with its index and
/// time [s] (for frames and outlines).
PlateRun spin_plate(const FemMaterial& material, FemModel model, TimeIntegrator integrator, int resolution,
                    MeshKind mesh, double h, double t_end, const ContinuumKernels& kernels, int samples = 100,
                    const std::function<void(const FemBody&, int, double)>& on_sample = {});

// --- the springs' mesh dependence --------------------------------------------------------------
/// A 1 m × 1 m sheet clamped on its left edge and pulled on its right edge by a traction of
/// 1e-3 E (spread over the edge's nodes by the length each one owns): its right edge's mean
/// displacement along x, divided by the 1-D answer σ L / E (1 for a bar free to narrow). None
/// when Newton's method fails (no flags the chapter accepts make it: the strain is 1e-3).
std::optional<double> sheet_stretch(const FemMaterial& material, FemModel model, MeshKind mesh, int n,
                                    const ContinuumKernels& kernels);
struct StretchRow {
  int n = 0;
  std::optional<double> regular, irregular;  ///< sheet_stretch on each mesh
  std::optional<double> difference() const;  ///< |irregular − regular| / regular, when both are there
};
std::vector<StretchRow> stretch_sweep(const FemMaterial& material, FemModel model,
                                      const std::vector<int>& sizes, const ContinuumKernels& kernels);

}  // namespace kit
