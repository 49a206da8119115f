#pragma once
// How kit/ode/butcher_tableau.hpp's and kit/ode/embedded_step.hpp's types cross the link (wire.hpp).
#include <tuple>

#include <kit/ode/butcher_tableau.hpp>
#include <kit/ode/embedded_step.hpp>

namespace kit {
inline auto fields(ButcherTableau& t) {
  return std::tie(t.name, t.c, t.a, t.b, t.b_hat, t.order, t.embedded_order, t.fsal);
}
template <class State>
auto fields(EmbeddedStep<State>& s) {
  return std::tie(s.y, s.error, s.last_stage, s.evaluations);
}
}  // namespace kit
