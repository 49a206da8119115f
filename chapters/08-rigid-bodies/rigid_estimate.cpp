// Chapter 8's runs priced from their step counts (rigid_estimate.hpp).
#include "rigid_estimate.hpp"

namespace kit {

RunEstimate estimate_rigid_runs(const RigidSetup& setup) {
  // Per simulated second of --t-end: six integrators at --dt (the side-by-side runs), six at each
  // of 1e-4, 1e-3, 1e-2 and 3e-2 s (the sweep), the scene's run, and GSL sampled every 1 ms (13
  // evaluations a sample at most); then the scene's drop, the two drops of 6 s at 1 ms, and the
  // trade's runs, six integrators each.
  const double per_second = 7 / setup.dt + 6 * (1e4 + 1e3 + 1e2 + 34) + 13e3;
  double trade = 0;
  for (long n : setup.trade_steps) trade += 6.0 * double(n);
  RunEstimate estimate;
  estimate.steps = per_second * setup.t_end + scene_drop_seconds / setup.dt + 12e3 + trade;
  estimate.seconds_per_step = 5e-7;  // the polar step's SVD, the slowest, is 4e-7 s on a 2020 laptop
  // 2000 samples of each run, the frames' states, and the drop's samples: a few MB at most.
  estimate.bytes = 8e6 + 2.0 * double(setup.frames) * sizeof(RigidState);
  return estimate;
}

}  // namespace kit
