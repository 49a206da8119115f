// ./kit bench cloth-implicit: the implicit cloth of chapter 7 on one core, on the sheet of Liu,
// Bargteil, O'Brien & Kavan 2013 ("Fast Simulation of Mass-Spring Systems", who report 50 ms a
// frame for it): 81×81 nodes over 1 m (structural, shear and 4-neighbour bend springs, K = 1e4
// N/m, 0.1 kg/m², gravity, the two corners of one edge pinned), h = 1/30 s, CG to 1e-3 relative:
//   1. one linearised backward Euler step (BackwardEulerStepper: filtered PCG of ex 7.3, Eigen's
//      CG, and the filtered CG preconditioned by a multigrid V-cycle), split into the springs'
//      Jacobian blocks (ex 7.1), the pattern scatter of A (ImplicitMatrix::assemble), the solve
//      (for multigrid, its set-up too) and the rest, on one state half a second into the swing;
//      and ex 7.2's rebuild from triplets against the scatter, checked equal first;
//   2. cost per simulated second against symplectic Euler (chapter 6) at 0.9 of its measured
//      stable step;
//   3. Liu et al. at 10 local/global iterations (LiuStepper);
//   4. Bullet's soft-body cloth at the same h (and at a game's 1/240 s), and every method's sag
//      over the first second against a fine reference (symplectic Euler at half the explicit
//      step): speed and accuracy side by side;
//   5. what bounds the solve: the bytes of one CG iteration against a triad measured in the same
//      run, from memory and at the solve's own working-set size.
// Timings live here, never in the tests.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <time.h>
#include <unistd.h>

#include <fmt/format.h>
#include <Eigen/IterativeLinearSolvers>

#include <kit/app/table.hpp>
#include <kit/base/stopwatch.hpp>
#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_implicit_kernels.hpp>
#include <kit/cloth/cloth_implicit_matrix.hpp>
#include <kit/cloth/cloth_implicit_step.hpp>
#include <kit/cloth/cloth_liu.hpp>
#include <kit/cloth/cloth_multigrid.hpp>
#include <kit/cloth/cloth_scene.hpp>
#include <kit/cloth/cloth_stability.hpp>
#include <kit/cloth/cloth_system.hpp>

#include "bandwidth.hpp"
#include "bullet_cloth.hpp"
#include "cloth_assembly.hpp"
#include "cloth_jacobian.hpp"
#include "cloth_kernels.hpp"
#include "cloth_pcg.hpp"
#include "cpu_clock.hpp"
#include "machine_note.hpp"

namespace {
using kit::bench::CpuClock,
    kit::bench::load_average;  // every time below is read from it; the triads keep bandwidth.hpp's wall clock

// Fastest of `samples` timings of `run` [CPU s per call], each repeating it for at least
// `min_seconds`: kit_bench::fastest on the CPU clock.
template <class Run>
double fastest(Run&& run, int samples, double min_seconds) {
  double best = INFINITY;
  for (int i = 0; i < samples; ++i) {
    const CpuClock clock;
    long calls = 0;
    do {
      run();
      ++calls;
    } while (clock.seconds() < min_seconds);
    best = std::min(best, clock.seconds() / double(calls));
  }
  return best;
}

constexpr int n = 81;              // nodes along each side: 6561 in all, Liu et al.'s sheet
constexpr double stiffness = 1e4;  // [N/m], every family
// [N·s/m], every family: μ/K = 1e-7 s, far below every step here, so that it moves neither the
// explicit stable step nor the motion; non-zero so that the damping blocks are assembled and timed.
constexpr double damping = 1e-3;
constexpr double density = 0.1;        // [kg/m²]
constexpr double h = 1.0 / 30;         // [s], one frame
constexpr double t_end = 1;            // [s] simulated in parts 2 to 4
constexpr double tolerance = 1e-3;     // relative residual of each CG solve
constexpr int warm_steps = 15;         // steps of h before part 1's state: mid-swing, a typical solve
constexpr double target_ms = 25;       // per implicit step, one core
constexpr double target_ratio = 10;    // implicit at least this much cheaper per simulated second
const kit::Vec3 gravity{0, -9.81, 0};  // [m/s²]

const kit::ImplicitKernels implicit_kernels{&kit::spring_stiffness_block, &kit::assemble_implicit_system,
                                            &kit::filtered_pcg};

// The sheet: horizontal (x, z) at height 1 m, held by the two corners of its j = 0 edge, so it
// swings down under gravity (bench_cloth-explicit's sheet, and Bullet's patch in bullet_cloth.hpp).
// No strain limit, drag or collider: each method's own dynamics.
kit::ClothScene make_scene() {
  kit::ClothScene scene;
  scene.name = "liu-sheet";
  scene.grid.nx = scene.grid.ny = n;
  scene.grid.width = scene.grid.height = 1;
  scene.grid.origin = kit::Vec3(-0.5, 1, -0.5);
  scene.grid.areal_density = density;
  scene.springs.structural = scene.springs.shear = scene.springs.bend = kit::SpringFamily{stiffness, damping};
  scene.springs.bend_layout = kit::BendLayout::four;
  scene.gravity = gravity;
  scene.pins = {kit::Pin{0, 0}, kit::Pin{-1, 0}};
  scene.dt = h;
  scene.t_end = t_end;
  return scene;
}

kit::ImplicitSettings settings_for(kit::ImplicitSolver solver) {
  kit::ImplicitSettings settings;
  settings.solver = solver;
  settings.cg_tolerance = tolerance;
  return settings;
}

struct State {
  kit::NodeArray x, v;
  double t = 0;
};
void restore(kit::ClothSystem& cloth, const State& state) {
  cloth.x = state.x, cloth.v = state.v, cloth.t = state.t;
}

double relative_difference(const Eigen::VectorXd& p, const Eigen::VectorXd& q) {
  return (p - q).cwiseAbs().maxCoeff() / q.cwiseAbs().maxCoeff();
}

// --- 1. one implicit step, piece by piece --------------------------------------------------------
struct StepSplit {
  double jacobian = 0, assembly = 0, forces_rhs = 0, solve = 0, whole = 0;  // [s], fastest samples
  double setup = 0;          // [s], of the solve: the multigrid's set-up for this A (mg only)
  double slowest_whole = 0;  // [s]: the spread of the samples, the timing noise
  int iterations = 0;        // CG iterations of the solve
  double residual = 0;       // its final relative residual
  Eigen::VectorXd dv;        // its answer
  Eigen::VectorXd exact;     // mg only: the same system solved to 1e-10
};

// Timings of several pieces of work taken in turn, sample after sample, so that a busy spell of
// the machine slows them alike: each piece's fastest and slowest sample [CPU s per call].
struct Timing {
  double fastest = INFINITY, slowest = 0;
};
std::vector<Timing> in_turn(const std::vector<std::function<void()>>& runs, int samples, double min_seconds) {
  std::vector<Timing> out(runs.size());
  for (int i = 0; i < samples; ++i)
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const double t = fastest(runs[k], 1, min_seconds);
      out[k].fastest = std::min(out[k].fastest, t), out[k].slowest = std::max(out[k].slowest, t);
    }
  return out;
}

// What one step of `solver` does at the state, each piece timed alone with the public API, the
// way BackwardEulerStepper::step calls it; and the whole step, from the same state each time.
StepSplit split_step(kit::ClothSystem& cloth, const State& state, kit::ImplicitSolver solver) {
  restore(cloth, state);
  const kit::Springs& springs = cloth.springs();
  const kit::NodeArray &x = state.x, &v = state.v;
  StepSplit out;
  std::vector<kit::Mat3> stiffness(springs.size());
  const auto jacobian = [&] {
    for (std::size_t s = 0; s < springs.size(); ++s)
      stiffness[s] = implicit_kernels.stiffness_block(x.row(springs.a[s]), x.row(springs.b[s]),
                                                      springs.rest[s], springs.stiffness[s], true);
  };
  kit::NodeArray f(x.rows(), 3);
  Eigen::VectorXd b, pull;
  const auto forces_rhs = [&] {  // f_n, then b = h (f_n + h ∂f/∂x v_n)
    cloth.forces()(x, v, f);
    kit::stiffness_times(springs, stiffness, v, pull);
    b = h * (kit::flatten(f) + h * pull);
  };
  kit::ImplicitMatrix matrix(springs, x.rows(), cloth.pins());
  const auto assemble = [&] {
    matrix.assemble(springs, x, stiffness, cloth.masses(), cloth.scene().drag, h);
  };
  jacobian(), forces_rhs(), assemble();  // each piece's inputs, before any is timed

  std::function<void()> solve;
  std::vector<kit::Mat3> filters(std::size_t(x.rows()), kit::Mat3::Identity());
  for (const std::int32_t p : cloth.pins()) filters[std::size_t(p)].setZero();
  kit::PcgResult result;
  kit::ImplicitMatrix constrained = matrix;  // pins by elimination, as the stepper does for CG
  Eigen::VectorXd bc = b;
  constrained.constrain(bc);
  Eigen::ConjugateGradient<kit::SparseMatrix, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(tolerance);
  cg.setMaxIterations(2000);
  kit::GridMultigrid multigrid(n, n, constrained.matrix);
  if (solver == kit::ImplicitSolver::pcg)
    solve = [&] { result = implicit_kernels.pcg(matrix.matrix, b, filters, tolerance, 2000); };
  else if (solver == kit::ImplicitSolver::mg)
    solve = [&] {
      multigrid.setup(constrained.matrix);
      result = kit::multigrid_pcg(constrained.matrix, bc, filters, multigrid, tolerance, 2000);
    };
  else
    solve = [&] {
      cg.compute(constrained.matrix);
      result.x = cg.solve(bc);
    };
  const auto setup = [&] { multigrid.setup(constrained.matrix); };

  kit::BackwardEulerStepper stepper(cloth, kit::ImplicitMethod::linearised, settings_for(solver),
                                    implicit_kernels);
  const auto whole = [&] {
    restore(cloth, state);
    stepper.step(cloth, h);
  };
  const auto copy = [&] { restore(cloth, state); };
  std::vector<std::function<void()>> pieces{jacobian, forces_rhs, assemble, solve, whole, copy};
  if (solver == kit::ImplicitSolver::mg) pieces.push_back(setup);
  const std::vector<Timing> t = in_turn(pieces, 5, 0.1);
  out.jacobian = t[0].fastest, out.forces_rhs = t[1].fastest, out.assembly = t[2].fastest;
  out.solve = t[3].fastest, out.whole = t[4].fastest - t[5].fastest;
  out.slowest_whole = t[4].slowest - t[5].fastest;
  if (solver == kit::ImplicitSolver::mg) out.setup = t[6].fastest;
  if (kit::filtered(solver))
    out.iterations = result.iterations, out.residual = result.residual;
  else
    out.iterations = int(cg.iterations()), out.residual = cg.error();
  out.dv = result.x;
  if (solver == kit::ImplicitSolver::mg) {
    multigrid.setup(constrained.matrix);
    out.exact = kit::multigrid_pcg(constrained.matrix, bc, filters, multigrid, 1e-10, 2000).x;
  }
  if (stepper.work.cg_iterations != long(out.iterations) * stepper.work.solves) {
    fmt::print(stderr, "bench: the stepper's solve took {} iterations, the piece timed alone {}\n",
               double(stepper.work.cg_iterations) / double(stepper.work.solves), out.iterations);
    std::exit(1);
  }
  restore(cloth, state);
  return out;
}

// --- 2 to 4: runs from rest over t_end -----------------------------------------------------------
constexpr int samples = 5;  // the sheet's mean drop at t = 0.2, 0.4, ..., 1 s

struct Run {
  std::string name;
  double h = 0;  // [s]
  long steps = 0;
  double seconds = 0;          // CPU time of the steps [s]
  kit::NodeArray x;            // positions at t_end
  double drops[samples] = {};  // mean drop at the sample times [m]
  double kinetic = NAN;        // [J] at t_end
  double energy = NAN;         // kinetic + springs + gravity at t_end [J] (kit's cloths only)
  double strain = NAN;         // largest structural (l − L0)/L0 at t_end
  double cg_per_step = NAN, cg_max = NAN;
  double first_step = NAN;  // [s], Liu: with its factorisation
};

double mean_drop(const kit::NodeArray& x) { return 1 - x.col(1).mean(); }

// Steps `step` `run.steps` times, timing the steps only, recording the mean drop at the sample
// times (the step nearest each) out of `positions`.
template <class Step, class Positions>
void timed_steps(Run& run, Step&& step, Positions&& positions) {
  double seconds = 0;
  for (long k = 0; k < run.steps; ++k) {
    const CpuClock clock;
    step();
    seconds += clock.seconds();
    if (k == 0) run.first_step = seconds;
    for (int q = 0; q < samples; ++q)
      if (k + 1 == std::lround(t_end * (q + 1) / samples / run.h)) run.drops[q] = mean_drop(positions());
  }
  run.seconds = seconds;
}

Run implicit_run(const kit::ClothScene& scene, const kit::Springs& springs, const char* name,
                 const std::function<std::unique_ptr<kit::ImplicitStepper>(const kit::ClothSystem&)>& make) {
  kit::ClothSystem cloth(scene, springs, kit::student_cloth_kernels());
  const auto stepper = make(cloth);
  Run run;
  run.name = name, run.h = h, run.steps = std::lround(t_end / h);
  timed_steps(
      run, [&] { stepper->step(cloth, h); }, [&]() -> const kit::NodeArray& { return cloth.x; });
  run.x = cloth.x, run.kinetic = cloth.kinetic(), run.energy = cloth.kinetic() + cloth.potential();
  run.strain = cloth.max_strain();
  if (stepper->work.solves > 0) {
    run.cg_per_step = double(stepper->work.cg_iterations) / double(stepper->work.solves);
    run.cg_max = double(stepper->work.max_cg_iterations);
  }
  return run;
}

Run explicit_run(const kit::ClothScene& scene, const kit::Springs& springs, const char* name, double dt) {
  kit::ClothSystem cloth(scene, springs, kit::student_cloth_kernels());
  Run run;
  run.name = name, run.steps = long(std::ceil(t_end / dt)), run.h = t_end / double(run.steps);
  timed_steps(
      run, [&] { cloth.step(kit::ClothIntegrator::symplectic_euler, run.h); },
      [&]() -> const kit::NodeArray& { return cloth.x; });
  run.x = cloth.x, run.kinetic = cloth.kinetic(), run.energy = cloth.kinetic() + cloth.potential();
  run.strain = cloth.max_strain();
  return run;
}

Run bullet_run(const char* name, int iterations, double step, const Eigen::VectorXd& masses) {
  kit_bench::BulletCloth cloth(n, density * 1.0, gravity, iterations);  // 1 m²
  Run run;
  run.name = name, run.h = step, run.steps = std::lround(t_end / step);
  timed_steps(
      run, [&] { cloth.step(step); }, [&] { return cloth.positions(); });
  run.x = cloth.positions();
  double links = 0;
  cloth.max_strain(run.strain, links);
  // Kinetic energy with the kit's node masses (Bullet spreads the mass evenly; the total is the same).
  run.kinetic = 0;
  const kit::NodeArray v = cloth.velocities();
  for (Eigen::Index i = 0; i < v.rows(); ++i) run.kinetic += 0.5 * masses[i] * v.row(i).squaredNorm();
  return run;
}

// How far the sheet has come down from its height at rest (1 m), and how far from the reference.
double lowest_drop(const kit::NodeArray& x) { return 1 - x.col(1).minCoeff(); }
// How far the sheet has turned about the line through its pins (z = −0.5) [degrees], read from its
// mean z as if it were a rigid plate: the mean z is −0.5 + 0.5 cos(angle), 0 at rest.
double turned(const kit::NodeArray& x) {
  return std::acos(std::clamp(2 * (x.col(2).mean() + 0.5), -1.0, 1.0)) * 180 / M_PI;
}
double rms_distance(const kit::NodeArray& x, const kit::NodeArray& reference) {
  return std::sqrt((x - reference).rowwise().squaredNorm().mean());
}

std::string strain_text(double strain) {
  if (!std::isfinite(strain)) return "blew up";
  if (strain > 1) return fmt::format("{:.1f} x L0", strain + 1);
  return fmt::format("{:.2f} %", 100 * strain);
}
const char* verdict(bool met) { return met ? "met" : "NOT met"; }

}  // namespace

int main() {
  const kit::Stopwatch total;  // wall time of the whole benchmark
  const double bandwidth = kit_bench::print_machine_note("the fastest of several samples where repeated");

  const kit::ClothScene scene = make_scene();
  const kit::Springs springs = kit::build_springs(scene.grid, scene.springs);
  kit::ClothSystem cloth(scene, springs, kit::student_cloth_kernels());
  fmt::print("The sheet: {}x{} nodes ({}), {} springs (structural {}, shear {}, bend {}), K = {:.0e} N/m, mu "
             "= {:.0e} N.s/m,\n"
             "{} kg/m^2 over 1 m^2, gravity, corners (0, 0) and ({}, 0) pinned; h = 1/30 s; CG to {:.0e} "
             "relative.\n\n",
             n, n, scene.grid.nodes(), springs.size(), springs.count(kit::SpringKind::structural),
             springs.count(kit::SpringKind::shear), springs.count(kit::SpringKind::bend), stiffness, damping,
             density, n - 1, tolerance);

  // --- 1 --------------------------------------------------------------------------------------
  {
    kit::BackwardEulerStepper warm(cloth, kit::ImplicitMethod::linearised,
                                   settings_for(kit::ImplicitSolver::pcg), implicit_kernels);
    for (int k = 0; k < warm_steps; ++k) warm.step(cloth, h);
  }
  const State state{cloth.x, cloth.v, cloth.t};
  const StepSplit pcg = split_step(cloth, state, kit::ImplicitSolver::pcg);
  const StepSplit cg = split_step(cloth, state, kit::ImplicitSolver::cg);
  const StepSplit mg = split_step(cloth, state, kit::ImplicitSolver::mg);
  fmt::print(
      "1. One linearised backward Euler step (Baraff & Witkin), at t = {:.2f} s of the swing (after {} "
      "steps\n"
      "   from rest), each piece timed alone on that state, then the whole BackwardEulerStepper::step\n",
      state.t, warm_steps);
  kit::Table split({"solver", "Jacobian blocks [ms]", "assembly [ms]", "solve [ms]", "of which MG set-up",
                    "rest [ms]", "of which f, b", "step [ms]", "slowest step", "CG iterations", "residual",
                    "ms / iteration"});
  for (const auto& [name, s] : {std::pair<const char*, const StepSplit&>{"filtered PCG (ex 7.3)", pcg},
                                {"Eigen CG, pins eliminated", cg},
                                {"multigrid PCG", mg}}) {
    const double rest = s.whole - s.jacobian - s.assembly - s.solve;
    split.add_row({name, kit::fixed(1e3 * s.jacobian, 2), kit::fixed(1e3 * s.assembly, 2),
                   kit::fixed(1e3 * s.solve, 2), s.setup > 0 ? kit::fixed(1e3 * s.setup, 2) : "",
                   kit::fixed(1e3 * rest, 2), kit::fixed(1e3 * s.forces_rhs, 2), kit::fixed(1e3 * s.whole, 2),
                   kit::fixed(1e3 * s.slowest_whole, 2), std::to_string(s.iterations),
                   fmt::format("{:.1e}", s.residual),
                   kit::fixed(1e3 * s.solve / std::max(s.iterations, 1), 3)});
  }
  split.print(std::cout);
  fmt::print(
      "   Each time is the fastest of 5 samples, the pieces and the step sampled in turn; 'slowest step' is "
      "the\n"
      "   slowest sample, the noise of this machine. rest: the step less the three pieces: the forces f_n "
      "and\n"
      "   b = h (f_n + h df/dx v_n) (timed alone in 'of which f, b'), the filters or the pins' elimination,\n"
      "   copies, and the update v += dv, x += h v.\n"
      "   CG iterations: the filtered PCG's count of products with A; Eigen's iterations(), one less than "
      "the\n"
      "   products of its loop (it stops inside the last one). The two solvers' dv differ by {:.1e} of the\n"
      "   largest |dv|{}.\n",
      relative_difference(pcg.dv, cg.dv),
      relative_difference(pcg.dv, cg.dv) == 0
          ? ": both are CG preconditioned by diag(A) on the free nodes, with the same arithmetic"
          : ", each solved to its own residual");
  fmt::print("   Error of dv against the same system solved to 1e-10, in the largest |dv|: diagonal CG "
             "{:.1e}, multigrid\n"
             "   PCG {:.1e}. Both stop at 1e-3 of b in residual, not in error: the residual hides error in "
             "the smooth,\n"
             "   slowly converging modes (small eigenvalues of A), which diagonal CG leaves and multigrid "
             "removes first.\n",
             relative_difference(cg.dv, mg.exact), relative_difference(mg.dv, mg.exact));
  const double best_ms = 1e3 * std::min({pcg.whole, cg.whole, mg.whole});
  fmt::print(
      "   Target: at most {} ms a step on one core (Liu et al. report 50 ms a frame): {:.1f} ms, {}.\n\n",
      target_ms, best_ms, verdict(best_ms <= target_ms));

  // Ex 7.2's triplets against the scatter, on the same inputs.
  {
    restore(cloth, state);
    const kit::NodeArray &x = state.x, &v = state.v;
    std::vector<kit::Mat3> stiffness(springs.size());
    for (std::size_t s = 0; s < springs.size(); ++s)
      stiffness[s] = kit::spring_stiffness_block(x.row(springs.a[s]), x.row(springs.b[s]), springs.rest[s],
                                                 springs.stiffness[s], true);
    kit::NodeArray f(x.rows(), 3);
    cloth.forces()(x, v, f);
    const kit::ImplicitSystemInput in{springs, x, v, f, cloth.masses(), stiffness, scene.drag, h};
    kit::SparseMatrix naive;
    Eigen::VectorXd b_naive, b_scatter, pull;
    kit::ImplicitMatrix scatter(springs, x.rows(), cloth.pins());
    const auto by_triplets = [&] { kit::assemble_implicit_system(in, naive, b_naive); };
    const auto by_scatter = [&] {
      scatter.assemble(springs, x, stiffness, cloth.masses(), scene.drag, h);
      kit::stiffness_times(springs, stiffness, v, pull);
      b_scatter = h * (kit::flatten(f) + h * pull);
    };
    by_triplets();
    by_scatter();
    const kit::SparseMatrix difference = naive - scatter.matrix;
    const double a_difference = difference.norm() / scatter.matrix.norm();
    const double b_difference = relative_difference(b_naive, b_scatter);
    const bool same =
        naive.nonZeros() == scatter.matrix.nonZeros() && a_difference < 1e-13 && b_difference < 1e-13;
    const double triplets = fastest(by_triplets, 5, 0.2), pattern = fastest(by_scatter, 5, 0.2);
    fmt::print("   A and b of the step, {} stored entries of A ({:.1f} per row), the same inputs:\n",
               scatter.matrix.nonZeros(), double(scatter.matrix.nonZeros()) / double(scatter.matrix.rows()));
    kit::Table assembly({"assembly", "ms", "triplets / scatter"});
    assembly.add_row({"ex 7.2: triplets, setFromTriplets", kit::fixed(1e3 * triplets, 2),
                      kit::fixed(triplets / pattern, 1)});
    assembly.add_row({"ImplicitMatrix: pattern once, scatter", kit::fixed(1e3 * pattern, 2), ""});
    assembly.print(std::cout);
    fmt::print("   Checked first: same pattern ({} and {} entries), ||A_triplets - A_scatter||_F / ||A||_F = "
               "{:.1e},\n"
               "   b to {:.1e} relative: {}.\n\n",
               naive.nonZeros(), scatter.matrix.nonZeros(), a_difference, b_difference,
               same ? "the same system, an honest comparison" : "NOT THE SAME");
    if (!same) return 1;
  }

  // --- 2 --------------------------------------------------------------------------------------
  // Symplectic Euler's largest stable step on the sheet's springs alone (no gravity, undamped),
  // bracketed around the prediction from omega_max at rest.
  const kit::ClothScene bare = kit::springs_only(scene);
  const kit::Springs bare_springs = kit::build_springs(bare.grid, bare.springs);
  const kit::OmegaMax omega =
      kit::omega_max(bare_springs, cloth.masses(), scene.grid.rest_positions(), cloth.pins(), 1e-6);
  const double predicted = kit::predicted_dt_max(kit::ClothIntegrator::symplectic_euler, omega.omega);
  const kit::MeasuredDtMax measured =
      kit::measure_dt_max(bare, bare_springs, kit::student_cloth_kernels(),
                          kit::ClothIntegrator::symplectic_euler, 0.5 * predicted, 2 * predicted);
  if (!(measured.stable > 0)) {
    fmt::print(stderr, "bench: no stable step measured for symplectic Euler\n");
    return 1;
  }
  const double explicit_dt = 0.9 * measured.stable;

  std::vector<Run> runs;
  runs.push_back(implicit_run(scene, springs, "backward Euler, filtered PCG", [](const kit::ClothSystem& c) {
    return std::make_unique<kit::BackwardEulerStepper>(
        c, kit::ImplicitMethod::linearised, settings_for(kit::ImplicitSolver::pcg), implicit_kernels);
  }));
  runs.push_back(implicit_run(scene, springs, "backward Euler, Eigen CG", [](const kit::ClothSystem& c) {
    return std::make_unique<kit::BackwardEulerStepper>(
        c, kit::ImplicitMethod::linearised, settings_for(kit::ImplicitSolver::cg), implicit_kernels);
  }));
  runs.push_back(implicit_run(scene, springs, "backward Euler, multigrid PCG", [](const kit::ClothSystem& c) {
    return std::make_unique<kit::BackwardEulerStepper>(
        c, kit::ImplicitMethod::linearised, settings_for(kit::ImplicitSolver::mg), implicit_kernels);
  }));
  runs.push_back(implicit_run(scene, springs, "Liu et al., 10 iterations", [](const kit::ClothSystem& c) {
    return std::make_unique<kit::LiuStepper>(c, 10);
  }));
  runs.push_back(explicit_run(scene, springs, "symplectic Euler, 0.9 dt_max", explicit_dt));
  runs.push_back(bullet_run("Bullet, 10 iterations", 10, h, cloth.masses()));
  runs.push_back(bullet_run("Bullet, defaults", 0, h, cloth.masses()));
  runs.push_back(bullet_run("Bullet, 10 iterations, h = 1/240", 10, 1.0 / 240, cloth.masses()));
  const Run& multigrid_run = runs[2];
  const Run& liu = runs[3];
  const Run& explicit_euler = runs[4];
  const Run& bullet = runs[5];
  // The reference: symplectic Euler at half the explicit step, its error about the distance
  // between the two (the method is first order).
  const Run reference = explicit_run(scene, springs, "reference", 0.5 * explicit_dt);

  fmt::print(
      "2. Cost per simulated second at K = {:.0e} N/m, from rest over {} s\n"
      "   Symplectic Euler's stable step on the springs alone (undamped, no gravity): omega_max = {:.4g} "
      "rad/s\n"
      "   (power iteration, {} iterations), predicted 2/omega_max = {:.3e} s, measured {:.3e} s (bisection,\n"
      "   {} runs of at most 2000 steps); run at 0.9 of the measured step.\n",
      stiffness, t_end, omega.omega, omega.iterations, predicted, measured.stable, measured.runs);
  kit::Table cost({"method", "h [s]", "steps", "ms / step", "CPU s per simulated s", "symplectic / this",
                   "CG iterations / step (max)"});
  for (const Run* r : {&runs[0], &runs[1], &runs[2], &runs[3], &runs[4]})
    cost.add_row(
        {r->name, fmt::format("{:.3e}", r->h), std::to_string(r->steps),
         kit::fixed(1e3 * r->seconds / double(r->steps), 3), kit::fixed(r->seconds / t_end, 3),
         r == &explicit_euler ? "" : kit::fixed(explicit_euler.seconds / r->seconds, 1),
         std::isfinite(r->cg_per_step) ? fmt::format("{:.0f} ({:.0f})", r->cg_per_step, r->cg_max) : ""});
  cost.print(std::cout);
  const double ratio = explicit_euler.seconds / std::min({runs[0].seconds, runs[1].seconds, runs[2].seconds});
  fmt::print(
      "   Target: backward Euler at least {:.0f}x cheaper per simulated second than symplectic Euler at its\n"
      "   stable step: {:.1f}x with the faster solver, {}.\n\n",
      target_ratio, ratio, verdict(ratio >= target_ratio));

  // --- 3 --------------------------------------------------------------------------------------
  const double liu_step = (liu.seconds - liu.first_step) / double(liu.steps - 1);
  fmt::print(
      "3. Liu et al. 2013, 10 local/global iterations a step (LiuStepper): {:.2f} ms a step ({:.3f} ms an\n"
      "   iteration: the springs' directions, then three triangular solve pairs), after a first step of\n"
      "   {:.2f} ms that factorises M + h^2 L once (sparse Cholesky, SimplicialLDLT): {:.1f}x faster than a\n"
      "   backward Euler step with the filtered PCG ({:.2f} ms in the run from rest), {:.2f}x the time of "
      "one\n"
      "   with the multigrid PCG ({:.2f} ms).\n\n",
      1e3 * liu_step, 1e3 * liu_step / 10, 1e3 * liu.first_step,
      runs[0].seconds / double(runs[0].steps) / liu_step, 1e3 * runs[0].seconds / double(runs[0].steps),
      liu_step / (multigrid_run.seconds / double(multigrid_run.steps)),
      1e3 * multigrid_run.seconds / double(multigrid_run.steps));

  // --- 4 --------------------------------------------------------------------------------------
  double rest_energy = 0;
  {
    const kit::ClothSystem at_rest(scene, springs, kit::student_cloth_kernels());
    rest_energy = at_rest.potential();
  }
  fmt::print("4. Bullet {}.{:02d} soft-body cloth (float; structural and shear links, no bend) at the same h "
             "(and at a\n"
             "   game's 1/240 s), and every method's sheet against the reference, symplectic Euler at half "
             "the explicit\n"
             "   step (h = {:.3e} s, {:.1f} s of CPU). Drops from the height at rest (1 m). The sheet, its "
             "bend springs\n"
             "   as stiff as the others, swings about the line through its two pins almost as a rigid plate "
             "(a mean\n"
             "   drop of 0.5 sin(angle)).\n",
             btGetVersion() / 100, btGetVersion() % 100, reference.h, reference.seconds);
  std::vector<std::string> drop_headers{"mean drop [m] at t ="};
  for (int q = 0; q < samples; ++q)
    drop_headers.push_back(fmt::format("{:.1f} s", t_end * (q + 1) / samples));
  kit::Table swing(drop_headers);
  const auto add_drops = [&](const Run& r) {
    std::vector<std::string> row{r.name};
    for (const double d : r.drops) row.push_back(kit::fixed(d, 3));
    swing.add_row(row);
  };
  add_drops(reference);
  for (const Run& r : runs) add_drops(r);
  swing.print(std::cout);
  fmt::print(
      "   At t = {} s. turned: the angle about the pins' line that the mean z gives a rigid plate. Energy:\n"
      "   kinetic + springs + gravity, lost since rest (the kit's cloths; Bullet has no spring energy).\n",
      t_end);
  kit::Table accuracy({"method", "h [s]", "ms / step", "lowest drop [m]", "mean drop [m]", "turned [deg]",
                       "RMS to reference [m]", "kinetic [mJ]", "energy lost [mJ]", "max structural strain"});
  const auto add = [&](const Run& r) {
    accuracy.add_row({r.name, fmt::format("{:.3e}", r.h), kit::fixed(1e3 * r.seconds / double(r.steps), 3),
                      kit::fixed(lowest_drop(r.x), 4), kit::fixed(mean_drop(r.x), 4),
                      kit::fixed(turned(r.x), 0), kit::fixed(rms_distance(r.x, reference.x), 4),
                      kit::fixed(1e3 * r.kinetic, 2),
                      std::isfinite(r.energy) ? kit::fixed(1e3 * (rest_energy - r.energy), 2) : "",
                      strain_text(r.strain)});
  };
  add(reference);
  for (const Run& r : runs) add(r);
  accuracy.print(std::cout);
  const double reference_error = rms_distance(explicit_euler.x, reference.x);
  fmt::print(
      "   The reference's own error is about its distance to the explicit run at twice its step: {:.1e} m "
      "RMS.\n"
      "   Bullet, 10 iterations at h = 1/30 s: {:.3f} ms a step, {:.1f}x {} than a backward Euler step with "
      "the\n"
      "   multigrid PCG; its structural links end at {}:\n   {}.\n\n",
      reference_error, 1e3 * bullet.seconds / double(bullet.steps),
      std::max(bullet.seconds, multigrid_run.seconds) / std::min(bullet.seconds, multigrid_run.seconds),
      bullet.seconds < multigrid_run.seconds ? "faster" : "slower", strain_text(bullet.strain),
      bullet.strain > 1
          ? "more than twice their length, 10 projections a step across 80 cells do not hold the sheet"
          : "within twice their length");

  // --- 5 --------------------------------------------------------------------------------------
  // One CG iteration reads the matrix once (values 8 B and column indices 4 B per stored entry,
  // row starts 4 B per row) and, at the least, the vectors of the algorithm: q = A p (p read, q
  // written), pᵀq, x += α p, r −= α q, z = P⁻¹ r, rᵀz, p = z + β p: 12 reads and 5 writes of
  // 8 B per row, a write counting the read that brings its line in (as the triad's do): 22.
  // The filtered PCG also applies the filters, 72 B per node, twice: 48 B per row more.
  // The multigrid PCG adds a V-cycle to the filtered PCG's iteration, in single precision with
  // blocks padded to 4×3 floats (48 B, and 4 B of column): on the finest grid its copy of A
  // twice (the forward sweep and the residual after it read it once between them, the backward
  // sweep once more), each node's inverse diagonal block twice, and about six vectors of 16 B a
  // node; each coarser grid the same for its blocks.
  kit::ImplicitMatrix matrix(springs, state.x.rows(), cloth.pins());
  const double rows = double(matrix.matrix.rows()), entries = double(matrix.matrix.nonZeros());
  const double matrix_bytes = 12 * entries + 4 * (rows + 1);
  const double cg_bytes = matrix_bytes + 22 * 8 * rows;
  const double pcg_bytes = cg_bytes + 48 * rows;
  const kit::GridMultigrid levels(n, n, matrix.matrix);
  double coarse_blocks = 0;
  for (int l = 1; l < levels.levels(); ++l) coarse_blocks += double(levels.level_blocks(l));
  const double nodes = rows / 3;
  const double mg_bytes =
      pcg_bytes + 2 * (52 * entries / 9 + 48 * nodes) + 6 * 16 * nodes + 2 * 52 * coarse_blocks;
  // Flops: 2 per stored entry for A p; the V-cycle 2 per entry of A twice, and of each coarse grid.
  const double cg_flops = 2 * entries, mg_flops = cg_flops + 2 * 2 * (entries + 9 * coarse_blocks);
  const double working_set = matrix_bytes + 8 * 8 * rows;  // A and the five vectors, P⁻¹, b
  // The same triad over three arrays that together hold the solve's working set: the bandwidth of
  // the cache level the solve runs from.
  double in_cache_stream = 0;
  const double in_cache = kit_bench::triad_bandwidth(std::size_t(working_set / 24), in_cache_stream);
  fmt::print(
      "5. What bounds the solve: A has {:.0f} rows and {:.0f} stored entries ({:.1f} MB with its indices); "
      "the\n"
      "   solve's working set (A and eight vectors) is {:.1f} MB. A triad over three arrays of that total "
      "runs at\n"
      "   {:.1f} GB/s (from memory: {:.1f} GB/s). One iteration moves at least {:.1f} MB (CG), {:.1f} MB\n"
      "   (filtered PCG, its filters too) or {:.1f} MB (multigrid PCG: a V-cycle over {} grids, {:.0f} "
      "coarse\n"
      "   blocks), and does {:.1f} Mflop (2 per stored entry in A p; multigrid {:.1f}).\n",
      rows, entries, matrix_bytes / 1e6, working_set / 1e6, in_cache / 1e9, bandwidth / 1e9, cg_bytes / 1e6,
      pcg_bytes / 1e6, mg_bytes / 1e6, levels.levels(), coarse_blocks, cg_flops / 1e6, mg_flops / 1e6);
  kit::Table bound({"solver", "ms / iteration", "GB/s", "of triad (memory)", "of triad (working set)",
                    "bound (memory) [ms]", "bound (working set) [ms]", "GFLOP/s"});
  for (const auto& [name, s, bytes, flops] :
       {std::tuple<const char*, const StepSplit&, double, double>{"filtered PCG", pcg, pcg_bytes, cg_flops},
        {"Eigen CG", cg, cg_bytes, cg_flops},
        {"multigrid PCG", mg, mg_bytes, mg_flops}}) {
    const double per_iteration = (s.solve - s.setup) / std::max(s.iterations, 1);
    bound.add_row({name, kit::fixed(1e3 * per_iteration, 3), kit::fixed(bytes / per_iteration / 1e9, 1),
                   kit::fixed(bytes / per_iteration / bandwidth, 2),
                   kit::fixed(bytes / per_iteration / in_cache, 2), kit::fixed(1e3 * bytes / bandwidth, 3),
                   kit::fixed(1e3 * bytes / in_cache, 3), kit::fixed(flops / per_iteration / 1e9, 2)});
  }
  bound.print(std::cout);
  fmt::print("   bound: the time one iteration's bytes take at that bandwidth; the multigrid's ms / "
             "iteration leaves\n"
             "   its set-up out. Diagonal CG: at {:.0f} iterations a step its solve takes at least {:.1f} ms "
             "if A streams\n"
             "   from memory, {:.1f} ms at the bandwidth of a cache that holds it, far above a {} ms step "
             "whatever the\n"
             "   speed of one iteration. The multigrid PCG moves {:.1f}x the bytes of a CG iteration but "
             "needs {} of\n"
             "   them: at least {:.1f} ms from memory, {:.1f} ms from cache, {:.1f} ms measured, plus {:.1f} "
             "ms of set-up.\n",
             double(cg.iterations), 1e3 * cg.iterations * cg_bytes / bandwidth,
             1e3 * cg.iterations * cg_bytes / in_cache, target_ms, mg_bytes / cg_bytes, mg.iterations,
             1e3 * mg.iterations * mg_bytes / bandwidth, 1e3 * mg.iterations * mg_bytes / in_cache,
             1e3 * (mg.solve - mg.setup), 1e3 * mg.setup);
  fmt::print("\nThe whole benchmark: {:.0f} s.\n", total.seconds());
  return 0;
}
