#pragma once
// Symplectic (semi-implicit) Euler, in the order of the lecture's cloth loop (ERRATA item 7):
//   v_{k+1} = v_k + Δt a(t_k, x_k, v_k),   x_{k+1} = x_k + Δt v_{k+1}   (the NEW velocity).
// Explicit Euler would use v_k in the second line. On an undamped spring this one small change
// keeps the energy bounded for every Δt < 2/ω, where explicit Euler grows for every Δt.
#include <kit/base/not_implemented.hpp>
#include <kit/base/state.hpp>

namespace kit {

/// One step for x'' = a(t, x, v) with u = (x, v) of 2·D components (D positions, D velocities).
/// `accel(t, x, v)` returns the D accelerations [m/s²]. Evaluates accel once.
template <class Accel, int N, class Scalar>
Vec<N, Scalar> symplectic_euler_step(const Accel& accel, Scalar t, const Vec<N, Scalar>& u, Scalar dt) {
  static_assert(N % 2 == 0, "u = (x, v) needs as many velocities as positions");
  [[maybe_unused]] constexpr int D = N / 2;  // positions (and as many velocities); unused in the stub
  Vec<N, Scalar> next;
  // TODO(ex 2.3): update the velocities first, then move the positions with the NEW velocities
  throw kit::NotImplemented("ex 2.3", "symplectic_euler.hpp");
  return next;
}

}  // namespace kit
