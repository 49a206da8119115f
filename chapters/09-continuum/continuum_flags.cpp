#include "continuum_flags.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <kit/base/usage.hpp>

namespace kit {

void add_continuum_flags(ChapterApp& app, ContinuumFlags& f) {
  app.add_real("--young", f.young, "Young's modulus E [Pa] of every experiment's material",
               between(1e3, 1e12));
  app.add_real("--poisson", f.poisson, "Poisson's ratio ν", between(0, 0.49));
  app.add_real("--density", f.density, "density ρ [kg/m³]", between(1, 1e5));
  app.add_count("--resolution", f.resolution, "the spinning plate's cells per side", 2, 128);
  app.add_choice("--mesh", f.mesh, "the plate's mesh: regular (alternating diagonals) or irregular",
                 mesh_kind_names.flags());
  app.add_choice("--model", f.model, "the plate's model: linear, stvk or springs", fem_model_names.flags());
  app.add_choice("--integrator", f.integrator,
                 "the plate's integrator: explicit (symplectic Euler) or implicit",
                 time_integrator_names.flags());
  app.add_real("--dt", f.dt, "the plate's time step h [s]; 0: 0.9 of the explicit limit, or 1 ms implicit",
               between(0, 0.1));
  app.add_real("--t-end", f.t_end, "how long the plate spins [s]", positive(100));
  app.add_count("--frames", f.frames, "OBJ meshes of the spinning plate (0: none)", 0, 2000);
  app.add_divergence_flag();
  app.add_quick_flag("the cost of accuracy's cantilevers to 4 elements high, not 8");
  app.add_viewer_flag();
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
    throw UsageError(fmt::format("--dt {} s is longer than --t-end {} s: --dt must be at most --t-end",
                                 flags.dt, flags.t_end));
  return s;
}

double scene_step(const ContinuumSetup& s) {
  if (s.dt > 0) return s.dt;
  if (s.integrator == TimeIntegrator::implicit_euler) return 1e-3;
  const double& nu = s.material.poisson;
  const double wave_speed = std::sqrt(s.material.young / (s.material.density * (1 - nu * nu)));  // [m/s]
  return 0.9 * 0.5 * (plate_side / s.resolution) / wave_speed;
}

std::string describe_continuum_run(const ContinuumFlags& f) {
  return fmt::format(
      "--young {} Pa, --poisson {}, --density {} kg/m³, --resolution {}, --mesh {}, --model {}, "
      "--integrator {}, --dt {} s, --t-end {} s, --frames {}",
      f.young, f.poisson, f.density, f.resolution, f.mesh, f.model, f.integrator, f.dt, f.t_end, f.frames);
}

}  // namespace kit
