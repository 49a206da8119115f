#pragma once
// What a step of each kernel of chapter 1's round-off sweep costs, from short calibration runs
// of the sweep's own kernels (kit/run_estimate.hpp): the chapter says how long the sweep will
// take before it starts, and its progress line counts each step at its cost.
#include <kit/run_estimate.hpp>
#include <kit/step_budget.hpp>

#include "free_fall_euler.hpp"

namespace kit {

inline RoundoffCosts roundoff_costs(const FreeFall& fall, double t_end) {
  return {seconds_per_step([&](long n) { return explicit_error<double>(fall, t_end, n); }),
          seconds_per_step([&](long n) { return explicit_error<float>(fall, t_end, n); }),
          seconds_per_step([&](long n) { return implicit_error<float>(fall, t_end, n); })};
}

}  // namespace kit
