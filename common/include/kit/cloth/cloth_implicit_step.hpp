#pragma once
// Chapter 7's implicit steps of a cloth (lecture, "Schéma implicite"; ERRATA item 14):
//   - linearised backward Euler (Baraff & Witkin 1998): one linear solve per step,
//       (M − h ∂f/∂v − h² ∂f/∂x) Δv = h (f_n + h ∂f/∂x v_n),   v += Δv,   x += h v;
//   - Newton's backward Euler: that step, then Newton iterations on the nonlinear equation
//       g(Δv) = M Δv − h f(x_n + h (v_n + Δv), v_n + Δv) = 0
//     until it holds, to measure what the linearisation costs in accuracy;
//   - Liu et al. 2013 (cloth_liu.hpp), the third point on the speed/accuracy trade.
// Three solvers: Eigen's conjugate gradient with a diagonal preconditioner, pins eliminated and
// contacts answered after the step; the student's filtered PCG (ex 7.3), pins and contacts held
// by per-node filters inside the solve; and the same filtered CG preconditioned by a multigrid
// V-cycle on the cloth's grid (cloth_multigrid.hpp), pins eliminated too, the fast one.
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include <kit/base/enum_names.hpp>
#include <kit/cloth/cloth_implicit_matrix.hpp>
#include <kit/cloth/cloth_multigrid.hpp>
#include <kit/cloth/cloth_system.hpp>

namespace kit {

enum class ImplicitMethod { linearised, newton, liu };
/// Their names in --integrator (beside the explicit ones) and summaries, and in figures.
inline constexpr auto implicit_method_names = enum_names<ImplicitMethod>({
    {ImplicitMethod::linearised, "implicit-euler", "implicit Euler (linearised)"},
    {ImplicitMethod::newton, "newton", "implicit Euler (Newton)"},
    {ImplicitMethod::liu, "liu", "Liu et al. 2013"},
});
static_assert(implicit_method_names.in_order());
inline constexpr auto all_implicit_methods = implicit_method_names.all();
inline const char* flag_name(ImplicitMethod method) { return implicit_method_names.flag(method); }
inline const char* display_name(ImplicitMethod method) { return implicit_method_names.display(method); }

enum class ImplicitSolver { cg, pcg, mg };
/// Their names in --solver and summaries, and in figures.
inline constexpr auto implicit_solver_names = enum_names<ImplicitSolver>({
    {ImplicitSolver::cg, "cg", "Eigen CG"},
    {ImplicitSolver::pcg, "pcg", "filtered PCG"},
    {ImplicitSolver::mg, "mg", "multigrid PCG"},
});
static_assert(implicit_solver_names.in_order());
inline constexpr auto all_implicit_solvers = implicit_solver_names.all();
inline const char* flag_name(ImplicitSolver solver) { return implicit_solver_names.flag(solver); }
inline const char* display_name(ImplicitSolver solver) { return implicit_solver_names.display(solver); }
/// True when the solver holds pins and contacts with Baraff & Witkin's filters (pcg, mg).
inline bool filtered(ImplicitSolver solver) { return solver != ImplicitSolver::cg; }

struct ImplicitSettings {
  ImplicitSolver solver = ImplicitSolver::pcg;
  double cg_tolerance = 1e-3;      ///< relative residual of each linear solve, in (0, 1)
  int max_cg_iterations = 2000;    ///< products with A per solve
  int iterations = 10;             ///< Newton: the most iterations; Liu: local/global iterations
  bool clamp = true;               ///< (1 − L0/l) ≥ 0 in the stiffness blocks: A stays positive definite
  double newton_tolerance = 1e-6;  ///< ‖g‖ relative to ‖h f_n‖
};

/// What the implicit steps computed, counted (tests check these, never times).
struct ImplicitWork {
  long steps = 0;
  long solves = 0;              ///< linear solves
  long cg_iterations = 0;       ///< products with A, all solves
  long max_cg_iterations = 0;   ///< the most in one solve
  long unconverged_solves = 0;  ///< stopped at the iteration cap above the tolerance
  long newton_iterations = 0;   ///< linear solves of Newton's method (its first is the linearised step)
  long newton_unconverged = 0;  ///< steps whose Newton iterations ran out above the tolerance
  long local_global = 0;        ///< Liu's local/global iterations
  long factorizations = 0;      ///< Liu's sparse Cholesky factorisations
  long multigrid_setups = 0;    ///< multigrid hierarchies built for a matrix (--solver mg)
  long blocks = 0;              ///< spring stiffness blocks evaluated (ex 7.1)
  long assemblies = 0;          ///< matrices scattered
  long filtered_nodes = 0;      ///< node-steps held on a collider inside the solve
  double worst_residual = 0;    ///< the largest final relative residual of a solve
  ImplicitWork& operator+=(const ImplicitWork& other);
};

/// A step that cannot go on: the linear solve met negative curvature (A not positive definite,
/// --no-clamp) or returned a non-finite or growing answer. The run reports it and stops.
class SolveFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Steps one cloth (the one it was made for) implicitly.
class ImplicitStepper {
 public:
  virtual ~ImplicitStepper() = default;
  /// One step of h [s], then cloth.finish_step(h). Throws SolveFailed.
  virtual void step(ClothSystem& cloth, double h) = 0;
  ImplicitWork work;
};

/// Linearised backward Euler or Newton's backward Euler.
class BackwardEulerStepper : public ImplicitStepper {
 public:
  /// Throws std::invalid_argument when the kernels it needs (ex 7.1; ex 7.3 for pcg) are missing.
  BackwardEulerStepper(const ClothSystem& cloth, ImplicitMethod method, const ImplicitSettings& settings,
                       ImplicitKernels kernels);
  void step(ClothSystem& cloth, double h) override;

  /// The linearised step's Δv [m/s] for the cloth's present state, without moving it (for
  /// tests and the chapter's checks); with Newton, the converged Δv.
  NodeArray velocity_change(ClothSystem& cloth, double h);
  /// ‖g(Δv)‖ / ‖h f_n‖ after the last step's last iteration (Newton; 0 for linearised).
  double last_newton_residual = 0;
  const SparseMatrix& matrix() const { return matrix_.matrix; }

 private:
  void jacobian(const ClothSystem& cloth, const NodeArray& x);
  void set_filters(const ClothSystem& cloth, const NodeArray& f);
  void friction(ClothSystem& cloth, double h) const;
  Eigen::VectorXd solve(Eigen::VectorXd b, double tolerance);
  Eigen::VectorXd newton(ClothSystem& cloth, Eigen::VectorXd dv, double f_norm, double h);
  void filter(Eigen::VectorXd& w) const;

  ImplicitMethod method_;
  ImplicitSettings settings_;
  ImplicitKernels kernels_;
  ImplicitMatrix matrix_;
  std::vector<Mat3> stiffness_;  ///< per spring, ∂f_a/∂x_a
  std::vector<Mat3> filters_;    ///< per node, S
  /// A node held on a collider in this step: its normal, the collider's friction, and the
  /// normal force [N] that pressed it in at the start of the step.
  struct Hold {
    std::int32_t node;
    Vec3 normal;
    double friction, pressure;
  };
  std::vector<Hold> holds_;
  NodeArray f_, x1_, v1_;
  std::optional<GridMultigrid> multigrid_;  ///< --solver mg: its levels, made once for the mesh
};

/// The stepper a method needs for this cloth (Liu's: cloth_liu.hpp).
std::unique_ptr<ImplicitStepper> make_implicit_stepper(const ClothSystem& cloth, ImplicitMethod method,
                                                       const ImplicitSettings& settings,
                                                       ImplicitKernels kernels);

}  // namespace kit
