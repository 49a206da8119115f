// Chapter 9's runs priced in element steps (continuum_estimate.hpp).
#include "continuum_estimate.hpp"

#include <algorithm>
#include <cmath>

namespace kit {

RunEstimate estimate_continuum_runs(const ContinuumSetup& s) {
  // In element steps (an element's forces, ~35 ns): the fixed experiments take about 7e7 (the
  // explicit relaxation of the finest cantilever, 2.8e4 steps of 1280 elements, half of it). The
  // plate runs once a model (three), and once more for the OBJ meshes: each its steps times its
  // 2 n² elements times an element step's share of a step. Implicit: the stiffness (~11 element
  // steps) and the PCG's iterations, about 5.4 n (34 at n = 8, 383 at n = 71, bench_continuum),
  // at ~0.5 element steps each.
  const double elements = 2.0 * s.resolution * s.resolution;
  const double iterations = std::max(35.0, 5.4 * s.resolution);
  const double per_step = s.integrator == TimeIntegrator::implicit_euler ? 1 + 11 + 0.5 * iterations : 1;
  const double plates = 3 + (s.frames > 0 ? 1 : 0);
  RunEstimate e;
  e.steps = 7e7 + plates * std::ceil(s.t_end / scene_step(s)) * elements * per_step;
  e.unit = "element steps";
  e.seconds_per_step = 5e-8;        // an element's forces and their share of the solves, 2020 laptop
  e.bytes = 2e7 + elements * 3000;  // the implicit matrix's 81 entries an element and the solver's vectors
  return e;
}

}  // namespace kit
