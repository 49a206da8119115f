#pragma once
// What a step of each kernel of chapter 1's round-off sweep costs, from short calibration runs
// of the sweep's own kernels (kit/app/run_estimate.hpp): the chapter says how long the sweep will
// take before it starts, and its progress line counts each step at its cost.
#include <kit/app/run_estimate.hpp>
#include <kit/base/not_implemented.hpp>
#include <kit/ode/step_budget.hpp>

#include "free_fall_euler.hpp"

namespace kit {

/// Seconds per step of `kernel`, or 0 when its exercise is not written yet (the sweep skips it).
template <class Kernel>
double kernel_cost(Kernel&& kernel) {
  try {
    return seconds_per_step(kernel);
  } catch (const NotImplemented&) {
    return 0.0;
  }
}

inline RoundoffCosts roundoff_costs(const FreeFall& fall, double t_end) {
  return {kernel_cost([&](long n) { return explicit_error<double>(fall, t_end, n); }),  // ex 1.1
          kernel_cost([&](long n) { return explicit_error<float>(fall, t_end, n); }),   // ex 1.1
          kernel_cost([&](long n) { return implicit_error<float>(fall, t_end, n); })};  // ex 1.3
}

}  // namespace kit
