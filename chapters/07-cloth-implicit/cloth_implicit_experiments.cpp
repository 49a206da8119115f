// Chapter 7's measurements of the implicit cloth (cloth_implicit_experiments.hpp).
#include "cloth_implicit_experiments.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <kit/base/random.hpp>
#include <kit/base/stopwatch.hpp>
#include <kit/cloth/cloth_stability.hpp>

namespace kit {
namespace {

Vec3 random_direction(Random& random) {
  for (;;) {
    const Vec3 d(random.symmetric(), random.symmetric(), random.symmetric());
    if (const double n = d.norm(); n > 0.1 && n <= 1) return d / n;
  }
}

/// The force on a of an undamped spring, f_a = −K (l − L0) x̂ [N]: what the block derives from.
Vec3 hooke(const Vec3& xa, const Vec3& xb, double rest, double stiffness) {
  const Vec3 gap = xa - xb;
  const double l = gap.norm();
  return -stiffness * (l - rest) / l * gap;
}

double lowest_eigenvalue(const Mat3& m) {
  return Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (m + m.transpose())).eigenvalues().minCoeff();
}

double max_abs(const SparseMatrix& m) {
  return m.nonZeros() ? Eigen::Map<const Eigen::VectorXd>(m.valuePtr(), m.nonZeros()).cwiseAbs().maxCoeff() : 0.0;
}

std::vector<Mat3> blocks(const Springs& springs, const NodeArray& x, SpringStiffnessBlock block, bool clamp) {
  std::vector<Mat3> out(springs.size());
  for (std::size_t s = 0; s < springs.size(); ++s)
    out[s] = block(x.row(springs.a[s]), x.row(springs.b[s]), springs.rest[s], springs.stiffness[s], clamp);
  return out;
}

bool cholesky_succeeds(const SparseMatrix& a) {
  const Eigen::SparseMatrix<double> column_major = a;
  return Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>(column_major).info() == Eigen::Success;
}

double rms_distance(const NodeArray& a, const NodeArray& b) {
  return std::sqrt((a - b).rowwise().squaredNorm().mean());
}

std::vector<std::int32_t> pins_of(const ClothScene& scene) {
  std::vector<std::int32_t> pins;
  for (const Pin& p : scene.pins) pins.push_back(std::int32_t(pinned_node(scene.grid, p)));
  return pins;
}

}  // namespace

JacobianCheck check_stiffness_block(SpringStiffnessBlock block, int springs) {
  Random random(20261122);
  JacobianCheck c;
  c.springs = springs;
  for (int s = 0; s < springs; ++s) {
    const double rest = 0.1 + 1.9 * random.unit(), stiffness = std::pow(10.0, 4 * random.unit());
    const double length = rest * (0.5 + 1.5 * random.unit());
    const Vec3 xb(random.symmetric(), random.symmetric(), random.symmetric());
    const Vec3 xa = xb + length * random_direction(random);
    const Mat3 j = block(xa, xb, rest, stiffness, false);
    Mat3 numeric;
    const double step = 1e-6 * length;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = step * Vec3::Unit(k);
      numeric.col(k) = (hooke(xa + e, xb, rest, stiffness) - hooke(xa - e, xb, rest, stiffness)) / (2 * step);
    }
    c.finite_difference = std::max(c.finite_difference, (j - numeric).norm() / j.norm());
    c.asymmetry = std::max(c.asymmetry, (j - j.transpose()).norm() / j.norm());
    if (length < rest) {
      c.clamped_lowest = std::min(c.clamped_lowest, lowest_eigenvalue(-block(xa, xb, rest, stiffness, true)) / stiffness);
      c.unclamped_lowest = std::min(c.unclamped_lowest, lowest_eigenvalue(-j) / stiffness);
    }
  }
  return c;
}

AssemblyCheck check_assembly(const ClothScene& scene, const Springs& springs, ImplicitKernels kernels, double h) {
  AssemblyCheck c;
  const ClothGrid& grid = scene.grid;
  const Eigen::VectorXd masses = grid.node_masses();
  const ClothForces forces(springs, masses, scene.gravity, scene.drag);
  const std::vector<std::int32_t> pins = pins_of(scene);
  // A disturbed state: every node off its rest place by up to 2% of a cell, moving up to 0.1 m/s.
  Random random(7);
  NodeArray x = grid.rest_positions(), v(x.rows(), 3), f;
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    for (int k = 0; k < 3; ++k) x(i, k) += 0.02 * grid.dx() * random.symmetric(), v(i, k) = 0.1 * random.symmetric();
  forces(x, v, f);
  const std::vector<Mat3> stiffness = blocks(springs, x, kernels.stiffness_block, true);
  ImplicitMatrix kit_matrix(springs, x.rows(), pins);
  SparseMatrix a;
  Eigen::VectorXd b, kit_b;
  const ImplicitSystemInput input{springs, x, v, f, masses, stiffness, scene.drag, h};
  time_per_call([&] { return kernels.assemble(input, a, b), 0; }, c.triplet_seconds);
  time_per_call([&] { return kit_matrix.assemble(springs, x, stiffness, masses, scene.drag, h), 0; }, c.scatter_seconds);
  stiffness_times(springs, stiffness, v, kit_b);
  kit_b = h * (flatten(f) + h * kit_b);
  const SparseMatrix& ak = kit_matrix.matrix;
  c.rows = ak.rows(), c.nonzeros = ak.nonZeros();
  const double scale = max_abs(ak);
  c.matrix_difference = a.rows() == ak.rows() && a.cols() == ak.cols() ? max_abs(SparseMatrix(a - ak)) / scale : INFINITY;
  c.rhs_difference = b.size() == kit_b.size() ? (b - kit_b).cwiseAbs().maxCoeff() / kit_b.cwiseAbs().maxCoeff() : INFINITY;
  c.asymmetry = max_abs(SparseMatrix(a - SparseMatrix(a.transpose()))) / scale;
  c.definite = cholesky_succeeds(a);
  // The sheet squeezed to 70% in its plane, a little rumpled: compressed springs everywhere.
  const Vec3 centre = x.colwise().mean();
  NodeArray squeezed = x;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const Vec3 r = x.row(i).transpose() - centre;
    squeezed.row(i) = (centre + 0.7 * r + 0.05 * grid.dx() * random_direction(random)).transpose();
  }
  forces(squeezed, v, f);
  const std::vector<Mat3> unclamped = blocks(springs, squeezed, kernels.stiffness_block, false);
  kit_matrix.assemble(springs, squeezed, unclamped, masses, scene.drag, h);
  c.unclamped_definite = cholesky_succeeds(kit_matrix.matrix);
  std::vector<Mat3> filters(std::size_t(x.rows()), Mat3::Identity());
  for (const std::int32_t p : pins) filters[std::size_t(p)].setZero();
  c.unclamped_solve = kernels.pcg(kit_matrix.matrix, h * flatten(f), filters, 1e-8, int(3 * x.rows()));
  return c;
}

ClothScene test_sheet(const ClothScene& scene, int n, double stiffness) {
  ClothScene sheet = springs_only(at_longest_side(scene, n));
  sheet.gravity = scene.gravity.value_or(Vec3(0, -9.81, 0));
  if (sheet.pins.empty()) sheet.pins = {{0, -1}, {-1, -1}};
  double structural = 0;
  for (SpringKind kind : all_spring_kinds)
    if (const auto& family = sheet.springs.family(kind); family && structural == 0) structural = family->stiffness;
  for (auto* family : {&sheet.springs.structural, &sheet.springs.shear, &sheet.springs.bend})
    if (*family) (*family)->stiffness *= stiffness / structural;
  return sheet;
}

namespace {

ClothRunOptions implicit_run(ImplicitMethod method, const ImplicitSettings& settings, ImplicitKernels kernels,
                             double h, double t_end) {
  ClothRunOptions run;
  run.implicit = method;
  run.implicit_settings = settings;
  run.implicit_kernels = kernels;
  run.dt = h;
  run.t_end = t_end;
  run.samples = 1;
  return run;
}

long iterations_of(const ClothRecording& rec) {
  return rec.implicit.local_global > 0 ? rec.implicit.local_global : rec.implicit.cg_iterations;
}

}  // namespace

std::vector<StiffnessRow> stiffness_sweep(const ClothScene& scene, ClothKernels kernels, ImplicitKernels implicit,
                                          ImplicitSettings settings, const std::vector<double>& stiffnesses,
                                          double h, double t_end) {
  settings.iterations = experiment_iterations;
  std::vector<StiffnessRow> rows;
  for (const double k : stiffnesses) {
    const ClothScene sheet = test_sheet(scene, 8, k);
    const Springs springs = kernels.build_springs(sheet.grid, sheet.springs);
    StiffnessRow row;
    row.stiffness = k;
    const ClothSystem cloth(sheet, springs, kernels);
    row.predicted = predicted_dt_max(ClothIntegrator::symplectic_euler,
                                     omega_max(springs, cloth.masses(), cloth.x, cloth.pins()).omega);
    row.measured = measure_dt_max(springs_only(sheet), springs, kernels, ClothIntegrator::symplectic_euler,
                                  0.5 * row.predicted, 2 * row.predicted);
    for (const ImplicitMethod method : all_implicit_methods) {
      const ClothRecording rec = run_cloth(sheet, springs, kernels, implicit_run(method, settings, implicit, h, t_end));
      ImplicitStability s;
      s.method = method;
      s.energy_change = rec.samples.back().total() - rec.samples.front().total();
      s.failure = rec.failure;
      s.iterations = iterations_of(rec);
      const double tolerance = 1e-9 * (std::abs(rec.samples.front().total()) + 1);
      s.stable = rec.exploded_at < 0 && s.energy_change <= tolerance;
      row.implicit.push_back(s);
    }
    rows.push_back(row);
  }
  return rows;
}

Trade speed_accuracy_trade(const ClothScene& scene, ClothKernels kernels, ImplicitKernels implicit,
                           ImplicitSettings settings, int n, double stiffness, double t_end) {
  settings.iterations = experiment_iterations;
  Trade trade;
  trade.stiffness = stiffness, trade.n = n, trade.t_end = t_end;
  const ClothScene sheet = test_sheet(scene, n, stiffness);
  const Springs springs = kernels.build_springs(sheet.grid, sheet.springs);
  const ClothSystem at_rest(sheet, springs, kernels);
  const double omega = omega_max(springs, at_rest.masses(), at_rest.x, at_rest.pins()).omega;
  const auto run = [&](ClothRunOptions options, int samples = 1) {
    options.t_end = t_end, options.frames = 1, options.samples = samples;
    const Stopwatch clock;
    ClothRecording rec = run_cloth(sheet, springs, kernels, options);
    return std::pair{std::move(rec), clock.seconds()};
  };
  // The reference: RK4 at a twentieth of its stable step.
  ClothRunOptions fine;
  fine.integrator = ClothIntegrator::rk4;
  fine.dt = trade.reference_dt = t_end / std::ceil(t_end / (0.05 * predicted_dt_max(ClothIntegrator::rk4, omega)));
  const ClothRecording reference = run(fine, 200).first;  // 200 energy samples: the swing's largest kinetic energy
  const NodeArray& x_ref = reference.frames.back();
  const double e_ref = reference.samples.back().total();
  trade.reference_energy_drift = std::abs(e_ref - reference.samples.front().total());
  // The sheet starts at rest and the reference keeps its energy (to round-off): the energy the
  // motion exchanges is the most kinetic energy the swing reaches, taken from gravity and springs.
  for (const auto& sample : reference.samples) trade.energy_scale = std::max(trade.energy_scale, sample.kinetic);
  trade.dt_max = measure_dt_max(springs_only(sheet), springs, kernels, ClothIntegrator::symplectic_euler,
                                0.5 / omega, 4 / omega).estimate();
  const auto add = [&](const std::string& name, const std::string& key, ClothRunOptions options, int iterations) {
    const auto [rec, seconds] = run(options);
    SolverTradeRun r{name, key, options.dt, iterations};
    r.failed = rec.exploded_at >= 0;
    r.error = r.failed ? INFINITY : rms_distance(rec.frames.back(), x_ref);
    r.energy_lost = r.failed ? NAN : e_ref - rec.samples.back().total();
    r.seconds = seconds;
    trade.runs.push_back(r);
  };
  // Each explicit method from just inside its stable step down; each implicit from 1/30 s down.
  for (int k = 0; k <= 4; ++k) {
    ClothRunOptions o;
    o.integrator = ClothIntegrator::symplectic_euler;
    o.dt = t_end / std::ceil(t_end / (0.9 * trade.dt_max * std::ldexp(1.0, -k)));
    add(display_name(o.integrator), flag_name(o.integrator), o, 0);
    o.integrator = ClothIntegrator::rk4;
    o.dt = t_end / std::ceil(t_end / (0.8 * predicted_dt_max(ClothIntegrator::rk4, omega) * std::ldexp(1.0, -k)));
    if (k <= 3) add(display_name(o.integrator), flag_name(o.integrator), o, 0);
  }
  for (const ImplicitMethod method : all_implicit_methods)
    for (int k = 0; k <= (method == ImplicitMethod::newton ? 1 : 5); ++k) {
      const int iterations = method == ImplicitMethod::liu ? settings.iterations : 0;
      add(display_name(method), flag_name(method), implicit_run(method, settings, implicit, std::ldexp(1.0 / 30, -k), t_end),
          iterations);
    }
  for (const int iterations : {1, 3, 30, 100}) {
    ImplicitSettings more = settings;
    more.iterations = iterations;
    add(std::string(display_name(ImplicitMethod::liu)) + ", h = 1/120 s", "liu-iterations",
        implicit_run(ImplicitMethod::liu, more, implicit, 1.0 / 120, t_end), iterations);
  }
  return trade;
}

std::vector<SolverPoint> solver_behaviour(const ClothScene& scene, ClothKernels kernels, ImplicitKernels implicit,
                                          const ImplicitSettings& settings, const std::vector<double>& stiffnesses,
                                          const std::vector<double>& steps, double t_end) {
  std::vector<SolverPoint> points;
  for (const double k : stiffnesses) {
    const ClothScene sheet = test_sheet(scene, 12, k);
    const Springs springs = kernels.build_springs(sheet.grid, sheet.springs);
    for (const ImplicitSolver solver : all_implicit_solvers)
      for (const double h : steps) {
        ImplicitSettings s = settings;
        s.solver = solver;
        const ClothRecording rec =
            run_cloth(sheet, springs, kernels, implicit_run(ImplicitMethod::linearised, s, implicit, h, t_end));
        const ImplicitWork& w = rec.implicit;
        points.push_back({solver, k, h, w.solves ? double(w.cg_iterations) / double(w.solves) : 0.0,
                          w.max_cg_iterations, w.unconverged_solves});
      }
  }
  return points;
}

Linearisation linearisation_error(const ClothScene& scene, ClothKernels kernels, ImplicitKernels implicit,
                                  const ImplicitSettings& settings, double h, double stiffness, double warm_up) {
  const ClothScene sheet = test_sheet(scene, 12, stiffness);
  ClothSystem cloth(sheet, kernels.build_springs(sheet.grid, sheet.springs), kernels);
  const double omega = omega_max(cloth.springs(), cloth.masses(), cloth.x, cloth.pins()).omega;
  const double fine = warm_up / std::ceil(warm_up / (0.1 * predicted_dt_max(ClothIntegrator::rk4, omega)));
  while (cloth.t < warm_up - fine / 2) cloth.step(ClothIntegrator::rk4, fine);
  ImplicitSettings exact = settings;
  exact.cg_tolerance = 1e-10;
  BackwardEulerStepper linearised(cloth, ImplicitMethod::linearised, exact, implicit);
  exact.iterations = 30;
  BackwardEulerStepper newton(cloth, ImplicitMethod::newton, exact, implicit);
  Linearisation l;
  l.h = h;
  try {
    const NodeArray dv_lin = linearised.velocity_change(cloth, h), dv_newton = newton.velocity_change(cloth, h);
    l.difference = (dv_lin - dv_newton).norm() / dv_newton.norm();
  } catch (const SolveFailed& e) {
    l.failure = e.what();
    l.difference = NAN;
  }
  l.newton_iterations = newton.work.newton_iterations;
  l.newton_residual = newton.last_newton_residual;
  return l;
}

RunEstimate estimate_implicit_run(const ClothScene& scene, const ClothRunOptions& run, double cg_iterations) {
  RunEstimate e;
  const double nodes = double(scene.grid.nodes());
  const double springs = double(spring_count(scene.grid.nx, scene.grid.ny, scene.springs));
  const double nonzeros = 9 * (nodes + 2 * springs);  // a 3×3 block per node and two per spring
  e.steps = std::max(1.0, std::round(run.t_end / run.dt));
  const double per_step = run.implicit ? springs * 150e-9 + cg_iterations * nonzeros * 2e-9 : springs * 6e-9 * stages(run.integrator);
  const double newton = run.implicit == ImplicitMethod::newton ? run.implicit_settings.iterations : 1;
  e.seconds_per_step = run.implicit == ImplicitMethod::liu ? run.implicit_settings.iterations * (springs * 20e-9 + nodes * 200e-9)
                                                           : newton * per_step;
  // The matrix (value and column index), per-spring blocks (72 B), state and scratch, frames.
  e.bytes = nonzeros * 12 + springs * (72 + 61) + nodes * 30 * 24 + double(run.frames + 1) * nodes * 24;
  // --solver mg: its single-precision copy of A (52 B a block), the Galerkin plan (about five
  // 8 B terms a block) and the coarse grids (about half as many blocks again). Its iterations
  // cost three CG iterations each, and it needs a third of the default count or fewer.
  if (run.implicit_settings.solver == ImplicitSolver::mg) e.bytes += nonzeros / 9 * (52 + 40 + 26);
  return e;
}

}  // namespace kit
