#pragma once
// The judge's embedded_rk.hpp (ex 4.2): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/ode/butcher_tableau.hpp>
#include <kit/ode/embedded_step.hpp>

#include "remote/fields/embedded_rk.hpp"
#include "remote/judge.hpp"

namespace kit {
template <class Rhs, class State>
EmbeddedStep<State> embedded_step(const Rhs& f, const ButcherTableau& tableau, double t, const State& y,
                                  double h, const State& k1) {
  return remote::call<EmbeddedStep<State>>("embedded_step/" + remote::key<State>(),
                                           remote::callback<State(double, const State&)>(f), tableau, t, y, h,
                                           k1);
}
}  // namespace kit
