#pragma once
// The judge's symplectic_euler.hpp (ex 2.3): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <vector>

#include <kit/base/state.hpp>

#include "remote/judge.hpp"

namespace kit {
template <class Accel, int N, class Scalar>
Vec<N, Scalar> symplectic_euler_step(const Accel& accel, Scalar t, const Vec<N, Scalar>& u, Scalar dt) {
  using Half = Vec<N / 2, Scalar>;
  return remote::call<Vec<N, Scalar>>("symplectic_euler_step/" + remote::key<Vec<N, Scalar>>(),
                                      remote::callback<Half(Scalar, const Half&, const Half&)>(accel), t, u,
                                      dt);
}
}  // namespace kit

namespace kit::remote {
/// n steps of the student's symplectic Euler on x'' = −x (ω = 1 rad/s) from u0, run in the
/// student's program (a million calls across the pipe would take a minute): every state, u_1 … u_n.
inline std::vector<Vec2> symplectic_euler_oscillator_orbit(const Vec2& u0, double h, long n) {
  return call<std::vector<Vec2>>("symplectic_euler_oscillator_orbit", u0, h, n);
}
}  // namespace kit::remote
