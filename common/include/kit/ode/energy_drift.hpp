#pragma once
// The energy error of a fixed-step run over many periods: (u0, Δt, N, step, energy)
// → max |E/E0 − 1| over u_0 … u_N, E_N/E0, and samples of |E/E0 − 1| for a figure.
// Chapter 3: symplectic Euler's error oscillates but stays bounded; the others drift.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <kit/app/progress.hpp>

namespace kit {

struct EnergyDrift {
  double max_drift = 0;       ///< max over k of |E(u_k)/E(u_0) − 1|
  double final_ratio = 0;     ///< E(u_N)/E(u_0)
  std::vector<double> t;      ///< sample times kΔt [s], about `samples` of them and t_N
  std::vector<double> drift;  ///< |E/E0 − 1| at those times
  /// The time [s] of the first state whose energy overflowed (±Inf or NaN): the run diverged
  /// and stopped there, and max_drift and final_ratio describe the states before it.
  std::optional<double> diverged_at;
};

/// N = `steps` steps of `step` (u_k → u_{k+1}) from u0, with energy(u) in J.
template <class State, class Step, class Energy>
EnergyDrift energy_drift(const State& u0, double dt, long steps, Step&& step, Energy&& energy,
                         long samples = 2000) {
  EnergyDrift out;
  const double e0 = energy(u0);
  const long every = std::max(1L, steps / samples);
  State u = u0;
  State last_good = u0;
  for (long k = 0;; ++k) {  // states u_0 … u_N: N steps exactly
    const double drift = std::abs(energy(u) / e0 - 1);
    if (!std::isfinite(drift)) {  // diverged: a result, reported with its time, not inf or nan
      out.diverged_at = static_cast<double>(k) * dt;
      u = last_good;
      break;
    }
    last_good = u;
    out.max_drift = std::max(out.max_drift, drift);
    if (k % every == 0 || k == steps)
      out.t.push_back(static_cast<double>(k) * dt), out.drift.push_back(drift);
    if (k == steps) break;
    if ((k + 1) % progress_chunk == 0) progress_add(static_cast<double>(progress_chunk));
    u = step(u);
  }
  out.final_ratio = energy(u) / e0;
  return out;
}

}  // namespace kit
