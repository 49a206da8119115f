#pragma once
// What chapter 6's runs of a cloth scene cost before they start (app/run_estimate.hpp: how a
// chapter announces an estimate and refuses a run over the limits).
#include <kit/app/run_estimate.hpp>
#include <kit/cloth/cloth_run.hpp>

namespace kit {

/// What chapter 6's runs of a scene cost before they start: the scene once with each of the
/// four integrators and once more with the strain limit switched, in steps (progress counts one
/// per step) and the memory of the state, springs and kept frames. `stage_ns` is a
/// conservative cost of one spring in one force evaluation [ns].
RunEstimate estimate_cloth_chapter(const ClothScene& scene, const ClothRunOptions& options,
                                   double stage_ns = 6.0);

}  // namespace kit
