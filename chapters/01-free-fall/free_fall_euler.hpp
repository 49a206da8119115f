#pragma once
// Chapter 1's runs of the Euler methods (ex 1.1–1.3) on free fall: the lecture's loop, both
// matrix forms, and the errors its order and round-off sweeps measure. Not an exercise: it only
// wires the selected methods to the free-fall model (kit/problems/free_fall.hpp).
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <kit/app/report.hpp>
#include <kit/base/measure.hpp>
#include <kit/base/stopwatch.hpp>
#include <kit/ode/fixed_steps.hpp>
#include <kit/ode/reference_solver.hpp>
#include <kit/ode/step_budget.hpp>
#include <kit/problems/free_fall.hpp>

#include "explicit_euler.hpp"
#include "implicit_euler.hpp"

namespace kit {

/// The lecture's loop `x = x + dt*v; v = v + dt*g`, n steps of dt [s]: explicit Euler (ex 1.1)
/// on f(t, u) = (v, g). Every evaluation of f is counted in `rhs_evals`.
inline Trajectory<Vec2> lecture_loop(const FreeFall& fall, double dt, long n, long& rhs_evals) {
  const CountingRhs<FreeFall> f{fall, rhs_evals};
  return record(fall.initial_state(), dt, n,
                [&](const Vec2& u) { return explicit_euler_step(f, 0.0, u, dt); });
}

/// The matrix forms over [0, T] in steps of h [s] (lecture, "Approche matricielle"), T/h + 1
/// samples each: explicit u_{k+1} = (I + hA) u_k + h b (ex 1.2) and implicit
/// (I − hA) u_{k+1} = u_k + h b (ex 1.3).
inline Trajectory<Vec2> explicit_matrix_form(const FreeFall& fall, double t_end, double h) {
  const ExplicitEulerAffine<2> forward(fall.affine(), h);
  const auto step = [&](const Vec2& u) { return forward.step(u); };
  return record(fall.initial_state(), h, whole_steps(t_end, h), step);
}
inline Trajectory<Vec2> implicit_matrix_form(const FreeFall& fall, double t_end, double h) {
  const ImplicitEulerAffine<2> backward(fall.affine(), h);
  const auto step = [&](const Vec2& u) { return backward.step(u); };
  return record(fall.initial_state(), h, whole_steps(t_end, h), step);
}

/// The runs of chapter 1's table over [0, T], all sampled at t_k = kΔt, k = 0..T/Δt. A run
/// whose exercise is not written yet is absent (the report said which exercise it waits for).
struct EulerRuns {
  std::optional<Trajectory<Vec2>> loop;        ///< the lecture's loop (explicit Euler on f, ex 1.1)
  std::optional<Trajectory<Vec2>> expl, impl;  ///< explicit (ex 1.2) and implicit (ex 1.3) matrix forms
  Trajectory<Vec2> reference;                  ///< GSL rk8pd at the same times
  long rhs_evals = 0;                          ///< evaluations of f by the loop: one a step
  Stats reference_stats;                       ///< what GSL's reference cost

  /// max_k |x_k(loop) − x_k(matrix form)| [m]: 0 when ex 1.1 and ex 1.2 agree to the last bit;
  /// none until both are written.
  std::optional<double> loop_vs_matrix() const {
    if (!loop || !expl) return std::nullopt;
    double d = 0;
    for (std::size_t k = 0; k < loop->size(); ++k) d = std::max(d, std::abs(loop->u[k][0] - expl->u[k][0]));
    return d;
  }
  /// Explicit Euler's run for the table: the matrix form (ex 1.2), or until it is written the
  /// lecture's loop (ex 1.1), which gives the same numbers to the last bit.
  const std::optional<Trajectory<Vec2>>& explicit_run() const { return expl ? expl : loop; }
  /// Evaluations of f by the loop, or none when the loop waits for ex 1.1.
  std::optional<long> loop_rhs_evals() const { return loop ? std::optional(rhs_evals) : std::nullopt; }
  /// max_k |x_k(GSL) − x̃(t_k)| [m].
  double reference_error(const FreeFall& fall) const {
    double d = 0;
    for (std::size_t k = 0; k < reference.size(); ++k)
      d = std::max(d, std::abs(reference.u[k][0] - fall.position(reference.t[k])));
    return d;
  }
};
/// x_k [m] of a run, or "-" when the run waits for its exercise.
inline ReportValue height_at(const std::optional<Trajectory<Vec2>>& run, std::size_t k) {
  return run ? ReportValue(run->u[k][0]) : ReportValue(std::monostate{});
}
/// Runs each method whose exercise is written; the report names those that wait for one.
inline EulerRuns run_euler(Report& report, const FreeFall& fall, double dt, double t_end) {
  EulerRuns r;
  const long n = whole_steps(t_end, dt);
  r.loop = report.attempt("the lecture's loop", [&] { return lecture_loop(fall, dt, n, r.rhs_evals); });
  r.expl =
      report.attempt("explicit Euler, matrix form", [&] { return explicit_matrix_form(fall, t_end, dt); });
  r.impl =
      report.attempt("implicit Euler, matrix form", [&] { return implicit_matrix_form(fall, t_end, dt); });
  std::vector<double> times(std::size_t(n) + 1);
  for (long k = 0; k <= n; ++k) times[std::size_t(k)] = double(k) * dt;  // as record() samples them
  r.reference = reference_solution(fall, 0.0, fall.initial_state(), times, {}, &r.reference_stats);
  return r;
}

/// x_n − x̃(nΔt) [m] after n explicit Euler steps of Δt = T/n on f(t, u) = (v, g), computed
/// in precision S (float or double). `rhs_evals`, when given, receives the evaluations of f.
template <class S>
double explicit_error(const FreeFall& fall, double t_end, long n, long* rhs_evals = nullptr) {
  using State = Vec<2, S>;
  const auto dt = S(t_end / double(n)), g = S(fall.g);
  auto f = [g](S, const State& u) { return State(u[1], g); };
  long evals = 0;
  CountingRhs<decltype(f)> counted{f, evals};
  const auto u = advance(fall.initial_state().cast<S>().eval(), n,
                         [&](const State& s) { return explicit_euler_step(counted, S(0), s, dt); });
  if (rhs_evals) *rhs_evals = evals;
  return double(u[0]) - fall.position(double(n) * double(dt));
}

/// The same for implicit Euler in matrix form.
template <class S>
double implicit_error(const FreeFall& fall, double t_end, long n) {
  const auto dt = S(t_end / double(n));
  const ImplicitEulerAffine<2, S> implicit(fall.affine().cast<S>(), dt);
  const auto u =
      advance(fall.initial_state().cast<S>().eval(), n, [&](const auto& s) { return implicit.step(s); });
  return double(u[0]) - fall.position(double(n) * double(dt));
}

/// |error| [m] against Δt = T/m [s], m = 10 … 10⁴ (4 a decade), for both Euler schemes in
/// double (ERRATA item 2): at the fixed time T (global, slope 1) and after one step of Δt
/// (local, slope 2). A scheme whose exercise is not written yet has empty sweeps.
struct EulerOrders {
  std::vector<double> dt;  ///< Δt [s] of every sweep, largest first
  Sweep global_explicit, global_implicit, local_explicit, local_implicit;
  /// The least-squares slope of each sweep, "-" for a scheme that did not run.
  std::vector<Field> slopes() const {
    const auto slope = [](const Sweep& s) { return s.dt.empty() ? ReportValue() : ReportValue(s.order()); };
    return {{"global_explicit", slope(global_explicit)},
            {"global_implicit", slope(global_implicit)},
            {"local_explicit", slope(local_explicit)},
            {"local_implicit", slope(local_implicit)}};
  }
  /// {"dt": [...], "global_explicit": [...] or null, ...}: the errors, one per Δt, for --json.
  nlohmann::json to_json() const {
    const auto errors = [](const Sweep& s) {
      return s.dt.empty() ? nlohmann::json() : nlohmann::json(s.error);
    };
    return {{"dt", dt},
            {"global_explicit", errors(global_explicit)},
            {"global_implicit", errors(global_implicit)},
            {"local_explicit", errors(local_explicit)},
            {"local_implicit", errors(local_implicit)}};
  }
};
inline EulerOrders measure_orders(Report& report, const FreeFall& fall, double t_end) {
  EulerOrders o;
  const auto counts = geometric_counts(10, 10'000, 4);
  for (long m : counts) o.dt.push_back(t_end / double(m));
  report.attempt("explicit Euler's orders", [&] {
    for (long m : counts) {
      o.global_explicit.add(t_end / double(m), std::abs(explicit_error<double>(fall, t_end, m)));
      o.local_explicit.add(t_end / double(m), std::abs(explicit_error<double>(fall, t_end / double(m), 1)));
    }
  });
  report.attempt("implicit Euler's orders", [&] {
    for (long m : counts) {
      o.global_implicit.add(t_end / double(m), std::abs(implicit_error<double>(fall, t_end, m)));
      o.local_implicit.add(t_end / double(m), std::abs(implicit_error<double>(fall, t_end / double(m), 1)));
    }
  });
  return o;
}

/// One run of the round-off sweep: explicit Euler in double over [0, T].
struct CostPoint {
  double dt = 0;       ///< Δt [s]
  long steps = 0;      ///< T/Δt
  long rhs_evals = 0;  ///< evaluations of f (one a step)
  double error = 0;    ///< |x_N − x̃(T)| [m]
  double seconds = 0;  ///< wall time of the run [s]; printed, never tested
};

/// The round-off sweep: |x_N − x̃(T)| [m] against Δt [s] as Δt shrinks until round-off wins.
struct Roundoff {
  Sweep doubles;                ///< explicit Euler in double, one point per step count of the sweep
  Sweep roundoff_part;          ///< | |error| − T·Δt·|g|/2 |: what truncation does not explain
  Sweep floats;                 ///< explicit Euler in float, on the float sweep's step counts
  Sweep floats_implicit;        ///< implicit Euler in float, the same
  std::vector<CostPoint> cost;  ///< what each double run cost, one per point of `doubles`
};

/// What the round-off sweep will do, as report fields: T [s], the double sweep's Δt range [s]
/// (asked for and used), its budget of steps a run and whether it raised the smallest Δt, and
/// the float sweep's smallest Δt [s] and budget.
inline std::vector<Field> sweep_plan(const StepSweep& doubles, const StepSweep& floats) {
  return {{"t_end", doubles.t_end},
          {"dt_max", doubles.dt_max},
          {"dt_min_requested", doubles.dt_min_requested},
          {"dt_min", doubles.dt_min},
          {"max_steps", doubles.max_steps},
          {"raised", doubles.raised()},
          {"float_dt_min", floats.dt_min},
          {"float_max_steps", floats.max_steps}};
}

/// Runs explicit Euler in double for every step count of `doubles`, and both Euler schemes in
/// float for those counts that `floats` allows (float stagnates long before: x + Δt·v rounds
/// back to x, so its sweep stops at a larger step). Both sweeps cover the same T. A scheme whose
/// exercise is not written yet leaves its curves empty.
inline Roundoff measure_roundoff(Report& report, const FreeFall& fall, const StepSweep& doubles,
                                 const StepSweep& floats) {
  Roundoff r;
  const double t_end = doubles.t_end, g = std::abs(fall.g);
  report.attempt("explicit Euler's round-off", [&] {
    for (long m : doubles.counts(4)) {
      const double h = t_end / double(m);
      CostPoint c{h, m};
      const auto run = [&] { return explicit_error<double>(fall, t_end, m, &c.rhs_evals); };
      c.error = std::abs(time_per_call(run, c.seconds));
      r.doubles.add(h, c.error);
      r.roundoff_part.add(h, std::abs(c.error - 0.5 * t_end * h * g));
      r.cost.push_back(c);
      if (m <= floats.most_steps()) r.floats.add(h, std::abs(explicit_error<float>(fall, t_end, m)));
    }
  });
  report.attempt("implicit Euler's round-off", [&] {
    const ProgressWeight slower(roundoff_implicit_weight);  // progress.hpp: its steps cost more
    for (long m : doubles.counts(4))
      if (m <= floats.most_steps())
        r.floats_implicit.add(t_end / double(m), std::abs(implicit_error<float>(fall, t_end, m)));
  });
  return r;
}

}  // namespace kit
