#pragma once
// Chapter 7's scene run priced before it starts (kit/app/run_estimate.hpp says how a chapter
// announces an estimate and refuses a run over the limits).
#include <kit/app/run_estimate.hpp>
#include <kit/cloth/cloth_run.hpp>

namespace kit {

/// What chapter 7's scene run costs before it starts: its steps, a conservative cost of one
/// (an implicit step: Jacobian, scatter and `cg_iterations` products with A), and the memory of
/// the matrix, the state and the kept frames. Its fixed experiments (small sheets) are not in it.
RunEstimate estimate_implicit_run(const ClothScene& scene, const ClothRunOptions& run,
                                  double cg_iterations = 100);

}  // namespace kit
