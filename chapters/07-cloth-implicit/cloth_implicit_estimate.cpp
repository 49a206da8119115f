// What chapter 7's scene run will cost (cloth_implicit_estimate.hpp): seconds a spring, a
// nonzero of A or a node per step, set on the long side so that a run is not refused late.
#include "cloth_implicit_estimate.hpp"

#include <algorithm>
#include <cmath>

namespace kit {

RunEstimate estimate_implicit_run(const ClothScene& scene, const ClothRunOptions& run, double cg_iterations) {
  RunEstimate e;
  const double nodes = double(scene.grid.nodes());
  const double springs = double(spring_count(scene.grid.nx, scene.grid.ny, scene.springs));
  const double nonzeros = 9 * (nodes + 2 * springs);  // a 3×3 block per node and two per spring
  e.steps = std::max(1.0, std::round(run.t_end / run.dt));
  const double per_step = run.implicit ? springs * 150e-9 + cg_iterations * nonzeros * 2e-9
                                       : springs * 6e-9 * stages(run.integrator);
  const double newton = run.implicit == ImplicitMethod::newton ? run.implicit_settings.iterations : 1;
  e.seconds_per_step = run.implicit == ImplicitMethod::liu
                           ? run.implicit_settings.iterations * (springs * 20e-9 + nodes * 200e-9)
                           : newton * per_step;
  // The matrix (value and column index), per-spring blocks (72 B), state and scratch, frames.
  e.bytes = nonzeros * 12 + springs * (72 + 61) + nodes * 30 * 24 + double(run.frames + 1) * nodes * 24;
  // --solver mg: its single-precision copy of A (52 B a block), the Galerkin plan (about five
  // 8 B terms a block) and the coarse grids (about half as many blocks again). Its iterations
  // cost three CG iterations each, and it needs a third of the default count or fewer.
  if (run.implicit_settings.solver == ImplicitSolver::mg) e.bytes += nonzeros / 9 * (52 + 40 + 26);
  return e;
}

}  // namespace kit
