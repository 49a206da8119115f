// Chapter 7's measurements of the implicit cloth (cloth_implicit_experiments.hpp).
#include "cloth_implicit_experiments.hpp"

#include <algorithm>
#include <cmath>

#include <kit/base/stopwatch.hpp>
#include <kit/cloth/cloth_stability.hpp>

namespace kit {
namespace {

double rms_distance(const NodeArray& a, const NodeArray& b) {
  return std::sqrt((a - b).rowwise().squaredNorm().mean());
}

}  // namespace

ClothScene test_sheet(const ClothScene& scene, int n, double stiffness) {
  ClothScene sheet = springs_only(at_longest_side(scene, n));
  sheet.gravity = scene.gravity.value_or(Vec3(0, -9.81, 0));
  if (sheet.pins.empty()) sheet.pins = {{0, -1}, {-1, -1}};
  double structural = 0;
  for (SpringKind kind : all_spring_kinds)
    if (const auto& family = sheet.springs.family(kind); family && structural == 0)
      structural = family->stiffness;
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

std::vector<StiffnessRow> stiffness_sweep(const ClothScene& scene, ClothKernels kernels,
                                          ImplicitKernels implicit, ImplicitSettings settings,
                                          const std::vector<double>& stiffnesses, double h, double t_end) {
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
      ClothRunOptions options = implicit_run(method, settings, implicit, h, t_end);
      options.samples = int(std::lround(t_end / h));  // one energy sample a step
      const ClothRecording rec = run_cloth(sheet, springs, kernels, options);
      ImplicitStability s;
      s.method = method;
      const double e0 = rec.samples.front().total();
      const double tolerance = 1e-9 * (std::abs(e0) + 1);  // [J]: round-off in E of a few joules
      s.energy_change = rec.samples.back().total() - e0;
      s.largest_rise = -INFINITY;
      for (std::size_t step = 1; step < rec.samples.size(); ++step) {
        const double rise = rec.samples[step].total() - rec.samples[step - 1].total();
        s.peak_gain = std::max(s.peak_gain, rec.samples[step].total() - e0);
        s.largest_rise = std::max(s.largest_rise, rise);
        s.rising_steps += rise > tolerance;
      }
      s.failure = rec.failure;
      s.iterations = iterations_of(rec);
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
  fine.dt = trade.reference_dt =
      t_end / std::ceil(t_end / (0.05 * predicted_dt_max(ClothIntegrator::rk4, omega)));
  const ClothRecording reference =
      run(fine, 200).first;  // 200 energy samples: the swing's largest kinetic energy
  const NodeArray& x_ref = reference.frames.back();
  const double e_ref = reference.samples.back().total();
  trade.reference_energy_drift = std::abs(e_ref - reference.samples.front().total());
  // The sheet starts at rest and the reference keeps its energy (to round-off): the energy the
  // motion exchanges is the most kinetic energy the swing reaches, taken from gravity and springs.
  for (const auto& sample : reference.samples)
    trade.energy_scale = std::max(trade.energy_scale, sample.kinetic);
  trade.dt_max = measure_dt_max(springs_only(sheet), springs, kernels, ClothIntegrator::symplectic_euler,
                                0.5 / omega, 4 / omega)
                     .estimate();
  const auto add = [&](const std::string& name, const std::string& key, ClothRunOptions options,
                       int iterations) {
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
    o.dt = t_end /
           std::ceil(t_end / (0.8 * predicted_dt_max(ClothIntegrator::rk4, omega) * std::ldexp(1.0, -k)));
    if (k <= 3) add(display_name(o.integrator), flag_name(o.integrator), o, 0);
  }
  for (const ImplicitMethod method : all_implicit_methods)
    for (int k = 0; k <= (method == ImplicitMethod::newton ? 1 : 5); ++k) {
      const int iterations = method == ImplicitMethod::liu ? settings.iterations : 0;
      add(display_name(method), flag_name(method),
          implicit_run(method, settings, implicit, std::ldexp(1.0 / 30, -k), t_end), iterations);
    }
  for (const int iterations : {1, 3, 30, 100}) {
    ImplicitSettings more = settings;
    more.iterations = iterations;
    add(std::string(display_name(ImplicitMethod::liu)) + ", h = 1/120 s", "liu-iterations",
        implicit_run(ImplicitMethod::liu, more, implicit, 1.0 / 120, t_end), iterations);
  }
  return trade;
}

std::vector<SolverPoint> solver_behaviour(const ClothScene& scene, ClothKernels kernels,
                                          ImplicitKernels implicit, const ImplicitSettings& settings,
                                          const std::vector<double>& stiffnesses,
                                          const std::vector<double>& steps, double t_end) {
  std::vector<SolverPoint> points;
  for (const double k : stiffnesses) {
    const ClothScene sheet = test_sheet(scene, 12, k);
    const Springs springs = kernels.build_springs(sheet.grid, sheet.springs);
    for (const ImplicitSolver solver : all_implicit_solvers)
      for (const double h : steps) {
        ImplicitSettings s = settings;
        s.solver = solver;
        const ClothRecording rec = run_cloth(sheet, springs, kernels,
                                             implicit_run(ImplicitMethod::linearised, s, implicit, h, t_end));
        const ImplicitWork& w = rec.implicit;
        points.push_back({solver, k, h, w.solves ? double(w.cg_iterations) / double(w.solves) : 0.0,
                          w.max_cg_iterations, w.unconverged_solves});
      }
  }
  return points;
}

Linearisation linearisation_error(const ClothScene& scene, ClothKernels kernels, ImplicitKernels implicit,
                                  const ImplicitSettings& settings, double h, double stiffness,
                                  double warm_up) {
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
    const NodeArray dv_lin = linearised.velocity_change(cloth, h),
                    dv_newton = newton.velocity_change(cloth, h);
    l.difference = (dv_lin - dv_newton).norm() / dv_newton.norm();
  } catch (const SolveFailed& e) {
    l.failure = e.what();
    l.difference = NAN;
  }
  l.newton_iterations = newton.work.newton_iterations;
  l.newton_residual = newton.last_newton_residual;
  return l;
}

}  // namespace kit
