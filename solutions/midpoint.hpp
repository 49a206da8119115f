#pragma once
// The midpoint Runge–Kutta method, exactly as the lecture writes it ("Runge Kutta"):
//   u_{k+1/2} = u_k + Δt/2 · F(t_k, u_k),   u_{k+1} = u_k + Δt · F(t_k + Δt/2, u_{k+1/2}).
// Two evaluations of F per step; second order. On free fall it is exact (lecture:
// x^k = x0 + kΔt v0 + (kΔt)²/2 g).
#include <kit/base/not_implemented.hpp>

namespace kit {

template <class Rhs, class State>
State midpoint_step(const Rhs& f, typename State::Scalar t, const State& u, typename State::Scalar dt) {
  // BEGIN SOLUTION ex 3.1: a half step of explicit Euler to the midpoint, then a full step with the midpoint's slope
  const State half = u + (dt / 2) * f(t, u);
  return u + dt * f(t + dt / 2, half);
  // END SOLUTION
}

}  // namespace kit
