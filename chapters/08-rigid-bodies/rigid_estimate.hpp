#pragma once
// What chapter 8's runs cost with its flags, before they start (kit/app/run_estimate.hpp).
#include <kit/app/run_estimate.hpp>
#include "rigid_flags.hpp"

namespace kit {

/// What every run of chapter 8 costs with these flags, from its step counts (run_estimate.hpp).
RunEstimate estimate_rigid_runs(const RigidSetup& setup);

}  // namespace kit
