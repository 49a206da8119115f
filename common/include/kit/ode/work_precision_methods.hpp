#pragma once
// The peers of the kit's work-precision diagrams, as WorkMethod (work_precision.hpp): GSL and
// Boost.Odeint run in the same process (peers.hpp), each at rtol = atol = tol from the first
// step h0, on y' = f(t, y), y(t0) = y0, up to t1. The production DOPRI5 is in
// dopri5_work_method.hpp; chapter 4 adds the methods students write
// (chapters/04-adaptive-rk/adaptive_rk_methods.hpp).
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <kit/app/look.hpp>
#include <kit/ode/peers.hpp>
#include <kit/ode/work_precision.hpp>

namespace kit {

/// The style of a GSL stepper's curve.
inline std::string gsl_look(GslStepper stepper) {
  switch (stepper) {
    case GslStepper::rkck:
      return look::gsl_rkck + " pt 4";
    case GslStepper::rkf45:
      return look::gsl_rkf45 + " pt 6";
    case GslStepper::rk8pd:
      return look::gsl_rk8pd + " pt 8";
    default:
      return look::prediction + " pt 1";
  }
}

/// GSL's odeiv2 driver with `stepper`: accepted and rejected steps from its evolve object.
template <int N, class Rhs>
WorkMethod<N> gsl_method(GslStepper stepper, Rhs f, double t0, const Vec<N>& y0, double t1, double h0,
                         std::vector<double> tolerances) {
  return {fmt::format("GSL {}", name(stepper)), gsl_look(stepper), std::move(tolerances),
          [=](double tol) { return gsl_peer(f, t0, y0, t1, stepper, tol, h0); }};
}

/// Boost.Odeint's controlled runge_kutta_dopri5: accepted steps only (rejected ones are unknown).
template <int N, class Rhs>
WorkMethod<N> boost_dopri5_method(Rhs f, double t0, const Vec<N>& y0, double t1, double h0,
                                  std::vector<double> tolerances) {
  return {"Boost.Odeint dopri5", look::boost_dopri5 + " pt 12", std::move(tolerances),
          [=](double tol) { return boost_dopri5_peer(f, t0, y0, t1, tol, h0); }};
}

/// 10^-lo, 10^-(lo+1), …, 10^-hi: the tolerances of a diagram.
inline std::vector<double> decades(int lo, int hi) {
  std::vector<double> tolerances;
  for (int e = lo; e <= hi; ++e) tolerances.push_back(std::pow(10.0, -e));
  return tolerances;
}

}  // namespace kit
