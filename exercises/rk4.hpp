#pragma once
// The classical fourth-order Runge–Kutta method: four evaluations of f per step, global error
// O(Δt⁴). Its stability region reaches the imaginary axis up to |z| = 2√2 ≈ 2.83.
#include <kit/base/not_implemented.hpp>

namespace kit {

template <class Rhs, class State>
State rk4_step(const Rhs& f, typename State::Scalar t, const State& u, typename State::Scalar dt) {
  // TODO(ex 3.2): slopes at the start, twice at the middle, at the end; weights 1, 2, 2, 1 over 6
  throw kit::NotImplemented("ex 3.2", "rk4.hpp");
}

}  // namespace kit
