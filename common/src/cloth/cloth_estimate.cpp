// Chapter 6's runs priced from their counts (cloth_estimate.hpp).
#include <kit/cloth/cloth_estimate.hpp>

#include <algorithm>
#include <cmath>

namespace kit {

RunEstimate estimate_cloth_chapter(const ClothScene& scene, const ClothRunOptions& options, double stage_ns) {
  RunEstimate e;
  const double nodes = double(scene.grid.nodes());
  const double springs = double(spring_count(scene.grid.nx, scene.grid.ny, scene.springs));
  const double steps = std::max(1.0, std::round(options.t_end / options.dt));
  double stages_per_step = stages(options.integrator);  // the strain-limit comparison run
  for (ClothIntegrator integrator : all_cloth_integrators) stages_per_step += stages(integrator);
  e.steps = 5 * steps;
  e.work = steps * stages_per_step;  // the progress line's units: force passes
  e.seconds_per_step = (springs * stages_per_step * stage_ns * 1e-9 + 5 * nodes * 40e-9) / 5;
  // State, masses and 11 scratch arrays of 3 doubles a node; 37 bytes a spring in the list and
  // 24 more in the force pass's copy; the kept frames, 24 bytes a node each.
  e.bytes = nodes * (13 * 24 + 16) + springs * 61 + double(options.frames + 1) * nodes * 24;
  return e;
}

}  // namespace kit
