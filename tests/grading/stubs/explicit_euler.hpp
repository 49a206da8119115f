#pragma once
// The judge's explicit_euler.hpp (ex 1.1, 1.2): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <string>

#include <kit/affine_system.hpp>

#include "remote/fields/affine_system.hpp"
#include "remote/judge.hpp"

namespace kit {

template <class Rhs, class State>
State explicit_euler_step(const Rhs& f, typename State::Scalar t, const State& u, typename State::Scalar dt) {
  using S = typename State::Scalar;
  return remote::call<State>("explicit_euler_step/" + remote::key<State>(), remote::callback<State(S, const State&)>(f),
                             t, u, dt);
}

template <int N, class Scalar = double>
class ExplicitEulerAffine {
 public:
  ExplicitEulerAffine(const AffineSystem<N, Scalar>& system, Scalar dt) : id_(remote::call<long>(entry("new"), system, dt)) {}
  Vec<N, Scalar> step(const Vec<N, Scalar>& u) const { return remote::call<Vec<N, Scalar>>(entry("step"), id_, u); }

 private:
  static std::string entry(const char* what) { return "ExplicitEulerAffine/" + remote::key<Vec<N, Scalar>>() + "/" + what; }
  long id_;
};

}  // namespace kit
