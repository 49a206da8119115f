#pragma once
// Chapter 1's runs of the Euler methods (ex 1.1–1.3) on free fall: the lecture's loop, both
// matrix forms, and the errors its order and round-off sweeps measure. Not an exercise: it only
// wires the selected methods to the free-fall model (kit/free_fall.hpp).
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include <kit/fixed_steps.hpp>
#include <kit/free_fall.hpp>
#include <kit/measure.hpp>
#include <kit/reference_solver.hpp>
#include <kit/step_budget.hpp>
#include <kit/stopwatch.hpp>

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

/// Both matrix forms over [0, T] in steps of h [s] (lecture, "Approche matricielle"):
/// explicit u_{k+1} = (I + hA) u_k + h b (ex 1.2), implicit (I − hA) u_{k+1} = u_k + h b (ex 1.3).
/// Returns (explicit, implicit), T/h + 1 samples each.
inline std::pair<Trajectory<Vec2>, Trajectory<Vec2>> matrix_forms(const FreeFall& fall, double t_end,
                                                                    double h) {
  const ExplicitEulerAffine<2> forward(fall.affine(), h);
  const ImplicitEulerAffine<2> backward(fall.affine(), h);
  const long m = whole_steps(t_end, h);
  return {record(fall.initial_state(), h, m, [&](const Vec2& u) { return forward.step(u); }),
          record(fall.initial_state(), h, m, [&](const Vec2& u) { return backward.step(u); })};
}

/// The runs of chapter 1's table over [0, T], all sampled at t_k = kΔt, k = 0..T/Δt.
struct EulerRuns {
  Trajectory<Vec2> loop;        ///< the lecture's loop (explicit Euler on f)
  Trajectory<Vec2> expl, impl;  ///< explicit and implicit Euler in matrix form
  Trajectory<Vec2> reference;   ///< GSL rk8pd at the same times
  long rhs_evals = 0;           ///< evaluations of f by the loop: one a step
  Stats reference_stats;        ///< what GSL's reference cost

  /// max_k |x_k(loop) − x_k(matrix form)| [m]: 0 when ex 1.1 and ex 1.2 agree to the last bit.
  double loop_vs_matrix() const {
    double d = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) d = std::max(d, std::abs(loop.u[k][0] - expl.u[k][0]));
    return d;
  }
  /// max_k |x_k(GSL) − x̃(t_k)| [m].
  double reference_error(const FreeFall& fall) const {
    double d = 0;
    for (std::size_t k = 0; k < reference.size(); ++k)
      d = std::max(d, std::abs(reference.u[k][0] - fall.position(reference.t[k])));
    return d;
  }
};
inline EulerRuns run_euler(const FreeFall& fall, double dt, double t_end) {
  EulerRuns r;
  r.loop = lecture_loop(fall, dt, whole_steps(t_end, dt), r.rhs_evals);
  std::tie(r.expl, r.impl) = matrix_forms(fall, t_end, dt);
  r.reference = reference_solution(fall, 0.0, fall.initial_state(), r.loop.t, {}, &r.reference_stats);
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
  const auto u = advance(fall.initial_state().cast<S>().eval(), n,
                         [&](const auto& s) { return implicit.step(s); });
  return double(u[0]) - fall.position(double(n) * double(dt));
}

/// |error| [m] against Δt = T/m [s], m = 10 … 10⁴ (4 a decade), for both Euler schemes in
/// double (ERRATA item 2): at the fixed time T (global, slope 1) and after one step of Δt
/// (local, slope 2).
struct EulerOrders {
  Sweep global_explicit, global_implicit, local_explicit, local_implicit;
  /// {"dt": [...], "global_explicit": [...], ...}: the errors, one per Δt, for the --json summary.
  nlohmann::json to_json() const {
    return {{"dt", global_explicit.dt}, {"global_explicit", global_explicit.error},
            {"global_implicit", global_implicit.error}, {"local_explicit", local_explicit.error},
            {"local_implicit", local_implicit.error}};
  }
};
inline EulerOrders measure_orders(const FreeFall& fall, double t_end) {
  EulerOrders o;
  for (long m : geometric_counts(10, 10'000, 4)) {
    const double h = t_end / double(m);
    o.global_explicit.add(h, std::abs(explicit_error<double>(fall, t_end, m)));
    o.global_implicit.add(h, std::abs(implicit_error<double>(fall, t_end, m)));
    o.local_explicit.add(h, std::abs(explicit_error<double>(fall, h, 1)));
    o.local_implicit.add(h, std::abs(implicit_error<double>(fall, h, 1)));
  }
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
  Sweep doubles;          ///< explicit Euler in double, one point per step count of the sweep
  Sweep roundoff_part;    ///< | |error| − T·Δt·|g|/2 |: what truncation does not explain
  Sweep floats;           ///< explicit Euler in float, on the float sweep's step counts
  Sweep floats_implicit;  ///< implicit Euler in float, the same
  std::vector<CostPoint> cost;  ///< what each double run cost, one per point of `doubles`
};

/// Runs explicit Euler in double for every step count of `doubles`, and both Euler schemes in
/// float for those counts that `floats` allows (float stagnates long before: x + Δt·v rounds
/// back to x, so its sweep stops at a larger step). Both sweeps cover the same T.
inline Roundoff measure_roundoff(const FreeFall& fall, const StepSweep& doubles, const StepSweep& floats) {
  Roundoff r;
  const double t_end = doubles.t_end, g = std::abs(fall.g);
  for (long m : doubles.counts(4)) {
    const double h = t_end / double(m);
    CostPoint c{h, m};
    const auto run = [&] { return explicit_error<double>(fall, t_end, m, &c.rhs_evals); };
    c.error = std::abs(time_per_call(run, c.seconds));
    r.doubles.add(h, c.error);
    r.roundoff_part.add(h, std::abs(c.error - 0.5 * t_end * h * g));
    r.cost.push_back(c);
    if (m > floats.most_steps()) continue;
    r.floats.add(h, std::abs(explicit_error<float>(fall, t_end, m)));
    const ProgressWeight slower(roundoff_implicit_weight);  // progress.hpp: its steps cost more
    r.floats_implicit.add(h, std::abs(implicit_error<float>(fall, t_end, m)));
  }
  return r;
}

}  // namespace kit
