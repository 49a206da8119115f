#include "continuum_flags.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <kit/base/usage.hpp>

namespace kit {

void add_continuum_flags(ChapterApp& app, ContinuumFlags& f) {
  app.add_real("--young", f.young, "Young's modulus E [Pa] of every experiment's material", between(1e3, 1e12));
  app.add_real("--poisson", f.poisson, "Poisson's ratio ν", between(0, 0.49));
  app.add_real("--density", f.density, "density ρ [kg/m³]", between(1, 1e5));
  app.add_count("--resolution", f.resolution, "the spinning plate's cells per side", 2, 128);
  app.add_choice("--mesh", f.mesh, "the plate's mesh: regular (alternating diagonals) or irregular",
                 mesh_kind_names.flags());
  app.add_choice("--model", f.model, "the plate's model: linear, stvk or springs", fem_model_names.flags());
  app.add_choice("--integrator", f.integrator, "the plate's integrator: explicit (symplectic Euler) or implicit",
                 time_integrator_names.flags());
  app.add_real("--dt", f.dt, "the plate's time step h [s]; 0: 0.9 of the explicit limit, or 1 ms implicit",
               between(0, 0.1));
  app.add_real("--t-end", f.t_end, "how long the plate spins [s]", positive(100));
  app.add_count("--frames", f.frames, "OBJ meshes of the spinning plate (0: none)", 0, 2000);
}

ContinuumSetup continuum_setup(const ContinuumFlags& flags) {
  ContinuumSetup s;
  s.material = {flags.young, flags.poisson, flags.density, 0.01};
  // add_choice let only the tables' names through: each finds its value.
  s.model = fem_model_names.parse(flags.model).value_or(s.model);
  s.mesh = mesh_kind_names.parse(flags.mesh).value_or(s.mesh);
  s.integrator = time_integrator_names.parse(flags.integrator).value_or(s.integrator);
  s.resolution = static_cast<int>(flags.resolution);
  s.dt = flags.dt;
  s.t_end = flags.t_end;
  s.frames = flags.frames;
  if (flags.dt > flags.t_end)
    throw UsageError(fmt::format("--dt {} s is longer than --t-end {} s: --dt must be at most --t-end", flags.dt,
                                 flags.t_end));
  return s;
}

double scene_step(const ContinuumSetup& s) {
  if (s.dt > 0) return s.dt;
  if (s.integrator == TimeIntegrator::implicit_euler) return 1e-3;
  const double& nu = s.material.poisson;
  const double wave_speed = std::sqrt(s.material.young / (s.material.density * (1 - nu * nu)));  // [m/s]
  return 0.9 * 0.5 * (plate_side / s.resolution) / wave_speed;
}

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
  e.seconds_per_step = 5e-8;  // an element's forces and their share of the solves, 2020 laptop
  e.bytes = 2e7 + elements * 3000;  // the implicit matrix's 81 entries an element and the solver's vectors
  return e;
}

std::string describe_continuum_run(const ContinuumFlags& f) {
  return fmt::format("--young {} Pa, --poisson {}, --density {} kg/m³, --resolution {}, --mesh {}, --model {}, "
                     "--integrator {}, --dt {} s, --t-end {} s, --frames {}",
                     f.young, f.poisson, f.density, f.resolution, f.mesh, f.model, f.integrator, f.dt, f.t_end,
                     f.frames);
}

}  // namespace kit
