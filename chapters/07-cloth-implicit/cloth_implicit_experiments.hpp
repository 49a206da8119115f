#pragma once
// Chapter 7's measurements of the implicit cloth (lecture, "Schéma implicite"): the stiffness an
// implicit step survives, the energy it removes,
// the speed/accuracy trade against the explicit methods, and what the linear solver costs.
// Each experiment runs on a small "test sheet" made from the scene (test_sheet below), so the
// chapter stays quick; counts are exact, times are what this machine measured.
#include <string>
#include <vector>

#include <kit/cloth/cloth_run.hpp>
#include <kit/cloth/cloth_stability.hpp>

namespace kit {

/// Newton's most iterations and Liu's iterations in the fixed experiments (the stiffness sweep
/// and the trade), whatever --iterations says: it sets the scene run's, and 10 keeps these
/// experiments' cost fixed.
inline constexpr int experiment_iterations = 10;

/// The experiments' sheet: `scene` at n nodes along its longer side, held at its pins (or at its
/// two last-row corners when it has none), under gravity (−9.81 m/s² in y if it has none), with
/// no spring damping, drag, collider or strain limit (so energy is conserved by the ODE), and
/// every spring family's stiffness scaled so that the structural one is `stiffness` [N/m].
ClothScene test_sheet(const ClothScene& scene, int n, double stiffness);

/// Figure 1: at each structural K, symplectic Euler's largest stable Δt (measured and
/// predicted) against the implicit methods at h = 1/30 s, which are stable when they neither
/// blow up nor fail and end the run with less energy than they started with. That is not a
/// fall at every step: the linearised step solves backward Euler's system with the forces'
/// Jacobian at the start of the step, and on a stiff sheet from rest (K ≥ 1e5 N/m at 1/30 s)
/// its energy rises above E(0) for a few steps before it falls. The energy is sampled at
/// every step, so the table says by how much.
struct ImplicitStability {
  ImplicitMethod method = ImplicitMethod::linearised;
  bool stable = false;
  double energy_change = 0;  ///< E(end) − E(0) [J]
  double peak_gain = 0;      ///< max over steps of E(t_k) − E(0), ≥ 0 [J]
  double largest_rise = 0;  ///< max over steps of E(t_k) − E(t_{k−1}), ≤ 0 when it falls at every step [J]
  long rising_steps = 0;  ///< steps whose energy rose above the last one's (beyond round-off)
  long iterations = 0;    ///< CG iterations (linearised, Newton) or local/global ones (Liu)
  std::string failure;
};
struct StiffnessRow {
  double stiffness = 0;    ///< structural K [N/m]
  double predicted = 0;    ///< symplectic Euler, 2/ω_max [s]
  MeasuredDtMax measured;  ///< symplectic Euler
  std::vector<ImplicitStability> implicit;
};
/// The sizes of chapter 7's fixed experiments: the lecture's, or --quick's (three stiffnesses in
/// the sweep, a trade over 1/3 s, the solver curves at their three longest steps, 1/30 to 1/120 s,
/// whose runs take 8 to 30 steps where 1/480 s takes 120: under half of the work). Every step of
/// the trade divides its duration: 1/3 s is 10 steps of 1/30 s, 320 of 1/960 s.
struct ImplicitExperimentSizes {
  std::vector<double> sweep_k{1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7};  ///< the sweep's K [N/m]
  double trade_t = 1;                                              ///< the trade's duration [s]
  std::vector<double> cg_k{1e2, 1e4, 1e6};                         ///< the CG curves' K [N/m]
  std::vector<double> cg_h{1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240, 1.0 / 480};  ///< and their h [s]
  static ImplicitExperimentSizes for_run(bool quick) {
    if (!quick) return {};
    return {{1e2, 1e4, 1e6}, 1.0 / 3, {1e2, 1e4, 1e6}, {1.0 / 30, 1.0 / 60, 1.0 / 120}};
  }
};

std::vector<StiffnessRow> stiffness_sweep(const ClothScene& scene, ClothKernels kernels,
                                          ImplicitKernels implicit, ImplicitSettings settings,
                                          const std::vector<double>& stiffnesses = {1e1, 1e2, 1e3, 1e4, 1e5,
                                                                                    1e6, 1e7},
                                          double h = 1.0 / 30, double t_end = 1);

/// Figures 2 and 3: one run of the test sheet, its error against the fine reference after t_end
/// and the wall time it took.
struct SolverTradeRun {
  std::string method;      ///< display name
  std::string key;         ///< the method's flag name, for styles and the summary
  double dt = 0;           ///< [s]
  int iterations = 0;      ///< Liu's local/global iterations (0: not Liu)
  double error = 0;        ///< RMS node-position error at t_end [m] (inf when it blew up)
  double energy_lost = 0;  ///< E_ref(t_end) − E(t_end) [J]: > 0 the method removed energy
  double seconds = 0;      ///< wall time of the run [s]
  bool failed = false;
};
struct Trade {
  double stiffness = 0;               ///< structural K [N/m]
  int n = 0;                          ///< nodes along the longer side
  double t_end = 0;                   ///< [s]
  double reference_dt = 0;            ///< RK4's step for the reference, a twentieth of its limit [s]
  double reference_energy_drift = 0;  ///< |E(t_end) − E(0)| of the reference [J]
  double energy_scale = 0;  ///< the reference's largest kinetic energy over [0, t_end], from rest [J]
  double dt_max = 0;        ///< symplectic Euler's measured limit [s]
  std::vector<SolverTradeRun> runs;
};
Trade speed_accuracy_trade(const ClothScene& scene, ClothKernels kernels, ImplicitKernels implicit,
                           ImplicitSettings settings, int n = 10, double stiffness = 1e4, double t_end = 1);

/// Figure 4: mean CG iterations per solve of the linearised step over a run, against h, at
/// several K, with Eigen's CG (pins eliminated) and the filtered PCG (ex 7.3).
struct SolverPoint {
  ImplicitSolver solver = ImplicitSolver::pcg;
  double stiffness = 0;  ///< [N/m]
  double h = 0;          ///< [s]
  double mean_iterations = 0;
  long max_iterations = 0;
  long unconverged = 0;
};
std::vector<SolverPoint> solver_behaviour(const ClothScene& scene, ClothKernels kernels,
                                          ImplicitKernels implicit, const ImplicitSettings& settings,
                                          const std::vector<double>& stiffnesses,
                                          const std::vector<double>& steps, double t_end = 0.25);

/// The linearisation's error in one step: the test sheet swinging (after `warm_up` s of fine
/// steps), one step of h by the linearised method and by Newton's.
struct Linearisation {
  double h = 0;
  double difference = 0;  ///< ‖Δv_lin − Δv_Newton‖ / ‖Δv_Newton‖
  long newton_iterations = 0;
  double newton_residual = 0;  ///< ‖g‖ / ‖h f_n‖ at the end
  std::string failure;         ///< why a solve failed (--no-clamp); empty when both steps were taken
};
Linearisation linearisation_error(const ClothScene& scene, ClothKernels kernels, ImplicitKernels implicit,
                                  const ImplicitSettings& settings, double h, double stiffness = 1e4,
                                  double warm_up = 0.2);

}  // namespace kit
