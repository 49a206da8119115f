#pragma once
// The classical fourth-order Runge–Kutta method: four evaluations of f per step, global error
// O(Δt⁴). Its stability region reaches the imaginary axis up to |z| = 2√2 ≈ 2.83.
#include <kit/base/not_implemented.hpp>

namespace kit {

template <class Rhs, class State>
State rk4_step(const Rhs& f, typename State::Scalar t, const State& u, typename State::Scalar dt) {
  // BEGIN SOLUTION ex 3.2: slopes at the start, twice at the middle, at the end; weights 1, 2, 2, 1 over 6
  const auto h = dt / 2;
  const State k1 = f(t, u);
  const State k2 = f(t + h, (u + h * k1).eval());
  const State k3 = f(t + h, (u + h * k2).eval());
  const State k4 = f(t + dt, (u + dt * k3).eval());
  return u + (dt / 6) * (k1 + 2 * k2 + 2 * k3 + k4);
  // END SOLUTION
}

}  // namespace kit
