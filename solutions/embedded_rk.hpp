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
  // BEGIN SOLUTION ex 4.2: compute each stage from the earlier ones (row i of A), then combine them with b and with b − b̂
  const int s = tableau.stages();
  std::vector<State> k(static_cast<std::size_t>(s), k1);
  for (int i = 1; i < s; ++i) {
    State stage = y;
    for (int j = 0; j < i; ++j)
      stage += (h * static_cast<double>(tableau.a[std::size_t(i)][std::size_t(j)])) * k[std::size_t(j)];
    k[std::size_t(i)] = f(t + static_cast<double>(tableau.c[std::size_t(i)]) * h, stage);
  }
  out.y = y;
  out.error = State::Zero(y.size());
  for (int i = 0; i < s; ++i) {
    const double b = static_cast<double>(tableau.b[std::size_t(i)]),
                 b_hat = static_cast<double>(tableau.b_hat[std::size_t(i)]);
    out.y += (h * b) * k[std::size_t(i)];
    out.error += (h * (b - b_hat)) * k[std::size_t(i)];
  }
  out.last_stage = k.back();
  out.evaluations = s - 1;
  // END SOLUTION
  return out;
}

}  // namespace kit
