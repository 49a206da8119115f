#pragma once
// The judge's explicit_euler.hpp (ex 1.1, 1.2): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <string>

#include <kit/problems/affine_system.hpp>

#include "remote/fields/affine_system.hpp"
#include "remote/judge.hpp"

namespace kit {

template <class Rhs, class State>
State explicit_euler_step(const Rhs& f, typename State::Scalar t, const State& u, typename State::Scalar dt) {
  return remote::call_one_step("explicit_euler_step", f, t, u, dt);
}

template <int N, class Scalar = double>
class ExplicitEulerAffine : public remote::RemoteStepper<Vec<N, Scalar>> {
 public:
  ExplicitEulerAffine(const AffineSystem<N, Scalar>& system, Scalar dt)
      : remote::RemoteStepper<Vec<N, Scalar>>("ExplicitEulerAffine/" + remote::key<Vec<N, Scalar>>(), system,
                                              dt) {}
};

}  // namespace kit
