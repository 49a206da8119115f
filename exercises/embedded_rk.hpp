#pragma once
// One step of any explicit embedded Runge–Kutta pair given by its Butcher tableau (the
// lecture's "Avec des ordres différents"): the stages k_i = f(t + c_i h, y + h Σ_j a_ij k_j),
// the solution y + h Σ b_i k_i, and the error estimate h Σ (b_i − b̂_i) k_i, all from the same
// stages: one step, not two (ERRATA item 11).
#include <vector>

#include <kit/base/not_implemented.hpp>
#include <kit/ode/butcher_tableau.hpp>
#include <kit/ode/embedded_step.hpp>

namespace kit {

/// `k1` = f(t, y) is passed in, so that an FSAL pair reuses its last stage as the next k_1.
/// Shapes: y, k1 and f(t, y) are vectors of one size; t, h in s.
template <class Rhs, class State>
EmbeddedStep<State> embedded_step(const Rhs& f, const ButcherTableau& tableau, double t, const State& y,
                                  double h, const State& k1) {
  EmbeddedStep<State> out;
  // TODO(ex 4.2): compute each stage from the earlier ones (row i of A), then combine them with b and with b − b̂
  throw kit::NotImplemented("ex 4.2", "embedded_rk.hpp");
  return out;
}

}  // namespace kit
