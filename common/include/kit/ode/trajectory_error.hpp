#pragma once
// The signed error of a run against a closed form, sample by sample.
#include <vector>

#include <kit/base/state.hpp>

namespace kit {

/// u_k[component] − exact(t_k) for every sample (t_k, u_k) of `run`, in the component's unit
/// (for free fall, component 0: x_k − x̃(t_k) [m], positive = above the exact parabola).
/// `exact(t)` is the closed form of that component at time t [s]. Same length as the run.
template <class State, class Exact>
std::vector<double> deviation(const Trajectory<State>& run, Exact&& exact, int component = 0) {
  std::vector<double> e;
  e.reserve(run.size());
  for (std::size_t k = 0; k < run.size(); ++k)
    e.push_back(static_cast<double>(run.u[k][component]) - exact(run.t[k]));
  return e;
}

}  // namespace kit
