#pragma once
// The peers chapter 4 and the benchmarks measure against, run in the same process on the same
// problem: GSL's odeiv2 steppers and Boost.Odeint's runge_kutta_dopri5. Each returns the
// state at t1, the right-hand-side evaluations it spent, and the steps it says it took.
#include <array>

#include <boost/numeric/odeint.hpp>

#include <kit/ode/reference_solver.hpp>
#include <kit/ode/work_precision.hpp>

namespace kit {

/// y(t1), evaluations, and the steps where the peer reports them (work_precision.hpp).
template <int N>
using PeerResult = WorkRun<N>;

/// GSL's driver with `stepper` at rtol = atol = tol, first step h0: accepted and rejected steps
/// from its evolve object.
template <int N, class Rhs>
PeerResult<N> gsl_peer(const Rhs& f, double t0, const Vec<N>& y0, double t1, GslStepper stepper, double tol,
                       double h0) {
  GslOptions options;
  options.stepper = stepper;
  options.rtol = options.atol = tol;
  options.h0 = h0;
  Stats stats;
  const auto end = reference_solution(f, t0, y0, {t1}, options, &stats);
  return {end.u.back(), stats.rhs_evals, stats.steps, stats.rejected};
}

/// Boost.Odeint's controlled runge_kutta_dopri5 through integrate_adaptive, on std::array state.
/// integrate_adaptive returns its accepted steps; it retries rejected ones inside try_step
/// without counting them, so `rejected` stays empty (unknown).
template <int N, class Rhs>
PeerResult<N> boost_dopri5_peer(const Rhs& f, double t0, const Vec<N>& y0, double t1, double tol, double h0) {
  using State = std::array<double, N>;
  namespace odeint = boost::numeric::odeint;
  long evaluations = 0;
  auto system = [&](const State& y, State& dydt, double t) {
    ++evaluations;
    Eigen::Map<Vec<N>>(dydt.data()) = f(t, Eigen::Map<const Vec<N>>(y.data()));
  };
  State y;
  Eigen::Map<Vec<N>>(y.data()) = y0;
  const auto accepted = odeint::integrate_adaptive(
      odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<State>()), system, y, t0, t1, h0);
  return {Eigen::Map<const Vec<N>>(y.data()), evaluations, static_cast<long>(accepted), std::nullopt};
}

}  // namespace kit
