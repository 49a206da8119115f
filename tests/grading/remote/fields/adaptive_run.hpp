#pragma once
// How kit/ode/adaptive_run.hpp's and kit/base/state.hpp's types cross the link (wire.hpp).
#include <tuple>

#include <kit/base/state.hpp>
#include <kit/ode/adaptive_run.hpp>

namespace kit {
inline auto fields(Stats& s) { return std::tie(s.rhs_evals, s.steps, s.rejected); }
inline auto fields(Divergence& d) { return std::tie(d.step, d.t, d.magnitude); }
template <class State>
auto fields(Trajectory<State>& t) {
  return std::tie(t.t, t.u, t.divergence);
}
template <class State>
auto fields(AdaptiveRun<State>& r) {
  return std::tie(r.accepted, r.step_sizes, r.rejected_t, r.rejected_h, r.stats, r.status, r.message);
}
}  // namespace kit
