#pragma once
// Driving a one-step method at a constant Δt: u_{k+1} = step(u_k).
#include <algorithm>
#include <cmath>
#include <limits>

#include <kit/app/progress.hpp>
#include <kit/base/state.hpp>

namespace kit {

/// u_n after n applications of `step` to u0. No storage: this is what sweeps over millions
/// of steps use. Reports its steps to the progress line, a chunk at a time.
template <class State, class Step>
State advance(State u, long n, Step&& step) {
  for (long done = 0; done < n;) {
    const long chunk = std::min(n - done, progress_chunk);
    // A local state: stores to it alias nothing, so what `step` reads (Δt, g) stays in registers
    // even when this function is not inlined (u, an argument, lives in the caller's memory).
    State v = u;
    for (long k = 0; k < chunk; ++k) v = step(v);
    u = v;
    done += chunk;
    progress_add(static_cast<double>(chunk));
  }
  return u;
}

/// The whole trajectory (t_k = kΔt, u_k) for k = 0..n. A diverging run is a result, not a
/// crash: the recording stops before the first state that is not finite or whose norm
/// exceeds `limit`, and trajectory.divergence says where.
template <class State, class Step>
Trajectory<State> record(State u, double dt, long n, Step&& step,
                         double limit = std::numeric_limits<double>::infinity()) {
  Trajectory<State> trajectory;
  trajectory.t.reserve(static_cast<std::size_t>(n) + 1);
  trajectory.u.reserve(static_cast<std::size_t>(n) + 1);
  trajectory.push(0.0, u);
  for (long k = 1; k <= n; ++k) {
    u = step(u);
    const double size = static_cast<double>(u.norm());
    if (!std::isfinite(size) || size > limit) {
      trajectory.divergence = Divergence{k, static_cast<double>(k) * dt, size};
      break;
    }
    trajectory.push(static_cast<double>(k) * dt, u);
    if (k % progress_chunk == 0) progress_add(static_cast<double>(progress_chunk));
  }
  return trajectory;
}

/// Number of steps of Δt that tile [0, T], or 0 when T/Δt is not a whole number (to 1e-9).
inline long whole_steps(double t_end, double dt) {
  const double ratio = t_end / dt;
  const double n = std::round(ratio);
  return (n >= 1 && std::abs(ratio - n) <= 1e-9 * n) ? static_cast<long>(n) : 0;
}

}  // namespace kit
