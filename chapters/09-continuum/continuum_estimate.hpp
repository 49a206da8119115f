#pragma once
// What chapter 9's runs cost with its flags, before they start (kit/app/run_estimate.hpp).
#include <kit/app/run_estimate.hpp>
#include "continuum_flags.hpp"

namespace kit {

/// What chapter 9's runs cost: the fixed experiments (about 10 s of element steps) and the scene.
RunEstimate estimate_continuum_runs(const ContinuumSetup& setup);

}  // namespace kit
