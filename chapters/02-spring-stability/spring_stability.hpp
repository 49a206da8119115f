#pragma once
// Chapter 2's measurements of the schemes (ex 2.1–2.4, 3.x) on the spring: runs at a step Δt,
// spectral radii, critical steps found by bisection, implicit Euler's damping, and the stability
// map over (ω·Δt, ζ). Not an exercise: it only wires the selected methods to the kit's
// stability tools (kit/ode/stability.hpp). ERRATA items 4–7.
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <kit/app/report.hpp>
#include <kit/ode/fixed_steps.hpp>
#include <kit/ode/reference_solver.hpp>
#include <kit/ode/stability.hpp>

#include "amplification.hpp"
#include "spring_steppers.hpp"

namespace kit {

/// The matrix M of one step u_{k+1} = M u_k of `scheme` on the unit oscillator (m = 1 kg,
/// K = 1 N/m, so ω = 1 rad/s and Δt = h; μ = 2ζ; rest length 0, so b = 0), read off the
/// scheme's own step: its columns are the steps from (1, 0) and (0, 1).
inline Mat2 step_matrix(Scheme s, double h, double zeta) {
  Spring unit;
  unit.mass = 1, unit.stiffness = 1, unit.rest_length = 0, unit.damping = 2 * zeta;
  const auto step = spring_stepper(s, unit, h);
  Mat2 m;
  m.col(0) = step(Vec2(1, 0)), m.col(1) = step(Vec2(0, 1));
  return m;
}

/// Spectral radius of one step of `scheme` on the oscillator, from its analysis: max |R(z)| over
/// z = λΔt (ex 2.4), or for symplectic Euler, which has no scalar R, the step matrix of the
/// student's own step (ex 2.3). h = ωΔt, ζ the damping ratio.
inline double spectral_radius(Scheme s, double h, double zeta) {
  if (s == Scheme::symplectic_euler) return spectral_radius(step_matrix(s, h, zeta));
  return spectral_radius([s](std::complex<double> z) { return amplification_factor(s, z); }, h, zeta);
}

/// The critical step of `scheme` on `spring` [s]: analytic (where the spectral radius reaches 1)
/// and measured (bisection on simulations long enough that a step 1e-4 past the limit doubles
/// the amplitude, so the measurement resolves the limit to about 1e-4, with at most `max_steps`
/// steps a run). NaN when measuring is not possible: no limit, or no bracket.
struct Critical {
  double analytic = NAN, measured = NAN;
};
inline Critical critical_step(Scheme s, const Spring& spring, long max_steps = 20'000'000) {
  const double w = spring.omega(), zeta = spring.damping_ratio();
  const double h = stability_limit([&](double x) { return spectral_radius(s, x, zeta); }, 10.0);
  if (!(h > 0) || !std::isfinite(h)) return {h / w, NAN};
  const long steps = std::clamp(long(10.0 / (spectral_radius(s, 1.001 * h, zeta) - 1.0)), 20'000L, max_steps);
  const Vec2 u0(spring.rest_length + 0.1, 0.0), rest(spring.rest_length, 0.0);
  const auto unstable = [&](double dt) { return grows(spring_stepper(s, spring, dt), u0, rest, steps); };
  if (unstable(0.5 * h / w) || !unstable(1.5 * h / w)) return {h / w, NAN};
  return {h / w, kit::critical_step(unstable, 0.5 * h / w, 1.5 * h / w, 2e-5)};
}

/// "undamped", "underdamped", "critically damped" or "overdamped", from the damping ratio ζ.
inline std::string damping_regime(double zeta) {
  return zeta == 0 ? "undamped" : zeta < 1 ? "underdamped" : zeta == 1 ? "critically damped" : "overdamped";
}

/// The critical step in words, where `stability_limit` found none: the text, or "{analytic:.4e}"
/// for a report sentence to print the value of its field "analytic" [s].
inline const char* limit_text(double analytic) {
  if (analytic == 0) return "none: unstable for every Δt (from ω·Δt = 0.01 on)";
  return std::isfinite(analytic) ? "{analytic:.4e}" : "none: stable for every Δt";
}

/// Where a run counts as diverged [units of u]: |u| past 1e8 times the start's distance from
/// rest (plus |L0|, so that the rest length itself is never "divergence").
inline double divergence_limit(const Spring& spring, const Vec2& u0) {
  return 1e8 * (u0 - Vec2(spring.rest_length, 0)).norm() + std::abs(spring.rest_length);
}

/// One scheme's run on the spring, n steps of Δt from u0, and what the chapter reports of it.
/// A run that diverges stops at its last finite state: its E(T), amplitude, growth and drift
/// say nothing about T and are NaN.
struct SpringRun {
  Trajectory<Vec2> trajectory;
  double energy_ratio = NAN;  ///< E(T)/E(0)
  double amplitude = NAN;     ///< sqrt(E(T)/E(0)): the amplitude at T as a multiple of the start's
  double growth = NAN;        ///< (E_N/E_0)^(1/2N): the amplitude's growth per step
  double max_drift = NAN;     ///< max |E/E0 − 1| over the run
  bool diverged() const { return bool(trajectory.divergence); }
  long steps() const { return long(trajectory.size()) - 1; }
};
inline SpringRun run_scheme(Scheme s, const Spring& spring, const Vec2& u0, double dt, long n) {
  SpringRun run{record(u0, dt, n, spring_stepper(s, spring, dt), divergence_limit(spring, u0))};
  if (run.diverged()) return run;
  const double e0 = spring.energy(u0);
  run.max_drift = 0;
  for (const Vec2& u : run.trajectory.u)
    run.max_drift = std::max(run.max_drift, std::abs(spring.energy(u) / e0 - 1));
  run.energy_ratio = spring.energy(run.trajectory.u.back()) / e0;
  run.amplitude = std::sqrt(run.energy_ratio);
  run.growth = std::pow(run.energy_ratio, 0.5 / double(std::max(1L, run.steps())));
  return run;
}

/// What the student's code can run so far: the schemes whose exercises are written (ex 1.2 and
/// 2.1 for explicit Euler, 2.2, 2.3, 3.1, 3.2), and whether the amplification factors R(z) of
/// ex 2.4 are. The chapter runs those, and says what each other part waits for.
struct Written {
  std::vector<Scheme> schemes;
  bool factors = false;
  bool has(Scheme s) const { return std::find(schemes.begin(), schemes.end(), s) != schemes.end(); }
};
/// Probes each scheme with one step and R(z) at one z; the report names what is not written yet.
inline Written written_parts(Report& report, const Spring& spring, const Vec2& u0, double dt) {
  Written w;
  w.schemes = written_schemes(report, spring, u0, dt);
  w.factors = report.attempt("amplification factors R(z)", [] {
    for (Scheme s : all_schemes)  // symplectic Euler has a 2×2 step matrix instead, from kit/
      if (s != Scheme::symplectic_euler) amplification_factor(s, {-0.5, 0.5});
  });
  return w;
}

/// The runs of every scheme in `schemes` at one Δt, by scheme.
using SpringRuns = std::map<Scheme, SpringRun>;
inline SpringRuns run_every_scheme(const Spring& spring, const Vec2& u0, double dt, long n,
                                   const std::vector<Scheme>& schemes) {
  SpringRuns runs;
  for (Scheme s : schemes) runs.emplace(s, run_scheme(s, spring, u0, dt, n));
  return runs;
}

/// The fmt format of growth factors whose largest is `largest`: fixed with 12 decimals while
/// readable (below 1e3), else scientific with 6 digits.
inline std::string factor_format(double largest) { return largest < 1e3 ? "{:.12f}" : "{:.5e}"; }

/// The spectral radius of one step at h = ωΔt and ζ, or "-" until R(z) is written (ex 2.4).
inline ReportValue spectral_radius(const Written& written, Scheme s, double h, double zeta) {
  return written.factors ? ReportValue(spectral_radius(s, h, zeta)) : ReportValue();
}

/// The largest growth factor a runs table prints: the measured growth of the runs that
/// finished, and, once R(z) is written (`factors`), every scheme's spectral radius at h = ωΔt and ζ.
inline double largest_factor(const SpringRuns& runs, double h, double zeta, bool factors) {
  double largest = 0;
  for (const auto& [s, run] : runs)
    largest = std::max({largest, run.diverged() ? 0 : run.growth, factors ? spectral_radius(s, h, zeta) : 0});
  return largest;
}

/// The textbook critical steps the chapter measures (ERRATA items 4–7): explicit Euler on the
/// damped spring (μ/K; ζ = 0.1 when the given spring is not underdamped, since μ/K is the
/// underdamped formula), symplectic Euler (2/ω) and RK4 (2√2/ω) on the undamped one.
struct CriticalCase {
  Scheme scheme;
  Spring spring;
  double closed_form;   ///< [s]
  const char* formula;  ///< "μ/K", "2/ω", "2√2/ω"
};
/// Those whose scheme is written.
inline std::vector<CriticalCase> textbook_critical_cases(const Spring& spring, const Written& written) {
  Spring damped = spring, undamped = spring;
  const double zeta = spring.damping_ratio(), w = spring.omega();
  if (!(zeta > 0 && zeta < 1)) damped.damping = 0.2 * std::sqrt(spring.stiffness * spring.mass);  // ζ = 0.1
  undamped.damping = 0;
  std::vector<CriticalCase> cases;
  for (const auto& c :
       {CriticalCase{Scheme::explicit_euler, damped, damped.damping / damped.stiffness, "μ/K"},
        {Scheme::symplectic_euler, undamped, 2.0 / w, "2/ω"},
        {Scheme::rk4, undamped, 2.0 * std::sqrt(2.0) / w, "2√2/ω"}})
    if (written.has(c.scheme)) cases.push_back(c);
  return cases;
}

/// The extremes: the given spring undamped, critically damped (ζ = 1) and overdamped (ζ = 3),
/// then undamped and stiff: ω×100, and ω = 1e6 rad/s (lecture, "Ressorts raides").
struct NamedSpring {
  const char* label;
  Spring spring;
};
inline std::vector<NamedSpring> extreme_springs(const Spring& spring) {
  std::vector<NamedSpring> springs;
  for (auto [label, k_factor, zeta] :
       {std::tuple{"undamped (μ = 0)", 1.0, 0.0},
        {"critical damping", 1.0, 1.0},
        {"overdamped", 1.0, 3.0},
        {"stiff, ω×100", 1e4, 0.0},
        {"stiff, ω = 1e6 rad/s", 1e12 * spring.mass / spring.stiffness, 0.0}}) {
    Spring variant = spring;
    variant.stiffness *= k_factor;
    variant.damping = 2 * zeta * std::sqrt(variant.stiffness * variant.mass);
    springs.push_back({label, variant});
  }
  return springs;
}

/// What `steps` steps of Δt do to every scheme on each of the extreme springs: one row per spring,
/// as report cells. `amplitudes`: the label, ζ, ω·Δt, then each scheme's amplitude after the
/// steps (null when it diverged); `divergences`: the label, then the step at which each scheme
/// diverged (null when it did not).
struct ExtremeRow {
  const char* label;
  std::vector<ReportValue> amplitudes, divergences;
};
inline std::vector<ExtremeRow> measure_extremes(const Spring& given, const Vec2& u0, double dt, long steps,
                                                const std::vector<Scheme>& schemes) {
  std::vector<ExtremeRow> rows;
  for (const auto& [label, spring] : extreme_springs(given)) {
    ExtremeRow row{
        label, {std::string(label), spring.damping_ratio(), spring.omega() * dt}, {std::string(label)}};
    for (const auto& [s, run] : run_every_scheme(spring, u0, dt, steps, schemes)) {
      if (run.diverged()) {
        row.amplitudes.emplace_back();  // null
        row.divergences.emplace_back(run.trajectory.divergence->step);
      } else {
        row.amplitudes.emplace_back(run.amplitude);
        row.divergences.emplace_back();
      }
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

/// A report column per scheme of `schemes` (in all_schemes' order): its name as header, its key, `format`.
inline std::vector<Column> scheme_columns(std::vector<Column> first, const std::vector<Scheme>& schemes,
                                          const std::string& format = "{}") {
  for (Scheme s : schemes) first.push_back({name(s), key(s), format});
  return first;
}

/// GSL's rk8pd on the spring's u' = A u + b (ex 2.1) against the closed form at t = kΔt:
/// max |x_gsl − x_exact| [m], or the reason GSL gave up (it has 2e6 steps: thousands suffice on
/// a normal spring, and an extreme one is reported, not waited for).
struct CrossCheck {
  double max_gap = NAN;     ///< [m]
  std::string unavailable;  ///< empty when GSL finished
  /// What to report: a sentence with its fields "reference_max_gap" (null when unavailable) and
  /// "reference_note".
  std::string sentence() const {
    if (!unavailable.empty()) return "GSL rk8pd cross-check unavailable on this spring: {reference_note}\n";
    return "GSL rk8pd against the closed form: max |x_gsl - x_exact| = {reference_max_gap:.3g} m\n";
  }
  std::vector<Field> fields() const {
    if (unavailable.empty()) return {{"reference_max_gap", max_gap}};
    return {{"reference_max_gap", ReportValue{}}, {"reference_note", unavailable}};
  }
};
inline CrossCheck gsl_cross_check(const Spring& spring, const Vec2& u0, double dt, long n) {
  std::vector<double> times;  // t_k = kΔt, k = 0..n
  for (long k = 0; k <= n; ++k) times.push_back(double(k) * dt);
  GslOptions options;
  options.max_steps = 2'000'000;
  try {
    const auto gsl = reference_solution(spring_system(spring), 0.0, u0, times, options);
    double gap = 0;
    for (std::size_t k = 0; k < times.size(); ++k)
      gap = std::max(gap, std::abs(gsl.u[k][0] - spring_motion(spring, u0, times[k])[0]));
    return {gap, {}};
  } catch (const SolverError& e) {
    return {NAN, e.what()};
  }
}

/// Implicit Euler's amplitude kept per step on `spring` made undamped, at h = ωΔt, measured over
/// a few steps (at most 50, and few enough that the energy stays above 1e-12 of its start).
inline double implicit_amplitude_per_step(const Spring& spring, const Vec2& u0, double h) {
  Spring undamped = spring;
  undamped.damping = 0;
  const long steps = std::clamp(long(27.0 / std::log(1 + h * h)), 1L, 50L);
  const auto end = advance(u0, steps, spring_stepper(Scheme::implicit_euler, undamped, h / undamped.omega()));
  return std::pow(undamped.energy(end) / undamped.energy(u0), 0.5 / double(steps));
}

/// A factor per step raised to the steps of one period of the motion, 2π/h for h = ωΔt: what
/// is kept of the amplitude over a period. Null when a period is shorter than one step.
inline ReportValue per_period(double per_step, double h) {
  if (2 * M_PI / h < 1) return {};
  return std::pow(per_step, 2 * M_PI / h);
}

/// Measured stability of `scheme` over ω·Δt = 0.1 … 4 and ζ = 0 … 2 (3000-step runs on the
/// unit oscillator, ω = 1 rad/s), beside the analytic boundary h(ζ) where the radius reaches 1.
struct StabilityMap {
  std::vector<double> stable_h, stable_zeta, unstable_h, unstable_zeta;  ///< the verdicts
  std::vector<double> boundary_h, boundary_zeta;                         ///< the analytic limit
};
/// The measured verdicts, and the analytic limit when R(z) is written (`factors`).
inline StabilityMap measure_stability_map(Scheme s, bool factors) {
  StabilityMap map;
  for (int i = 1; i <= 40; ++i) {
    for (int j = 0; j <= 20; ++j) {
      Spring unit;  // ω = 1 rad/s, so Δt = ω·Δt
      unit.mass = 1, unit.stiffness = 1, unit.rest_length = 0, unit.damping = 2 * 0.1 * j;
      const bool blows_up = grows(spring_stepper(s, unit, 0.1 * i), Vec2(1, 0), Vec2(0, 0), 3000);
      (blows_up ? map.unstable_h : map.stable_h).push_back(0.1 * i);
      (blows_up ? map.unstable_zeta : map.stable_zeta).push_back(0.1 * j);
    }
  }
  for (int j = 0; factors && j <= 200; ++j) {
    const double zeta = 0.01 * j;
    const double h = stability_limit([&](double x) { return spectral_radius(s, x, zeta); }, 4.0, 400, 1e-6);
    if (h > 0 && std::isfinite(h)) map.boundary_h.push_back(h), map.boundary_zeta.push_back(zeta);
  }
  return map;
}

/// The boundary |R(z)| = 1 of `scheme`'s stability region in the complex plane of z = λΔt, as
/// dots on [-4, 3] × [-3.5, 3.5]: (Re z, Im z).
inline std::pair<std::vector<double>, std::vector<double>> region_boundary(Scheme s) {
  const auto size = [s](double x, double y) { return std::abs(amplification_factor(s, {x, y})); };
  const auto dots = level_set_points(size, 1.0, -4, 3, -3.5, 3.5, 350, 350);
  std::vector<double> re, im;
  for (auto [x, y] : dots) re.push_back(x), im.push_back(y);
  return {re, im};
}

}  // namespace kit
