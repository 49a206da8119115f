#pragma once
// Chapter 9's flags: the material (--young, --poisson, --density) of every experiment, and the
// spinning plate's scene run (--resolution, --mesh, --model, --integrator, --dt, --t-end, --frames).
#include <string>

#include <kit/app/chapter_app.hpp>

#include "continuum_experiments.hpp"

namespace kit {

struct ContinuumFlags {
  double young = 1e9;  ///< [Pa]: a stiff polymer (nylon is 2–4 GPa)
  double poisson = 0.3;
  double density = 1000;  ///< [kg/m³]
  long resolution = 8;    ///< the plate's cells per side
  std::string mesh = "regular";
  std::string model = "stvk";
  std::string integrator = "explicit";
  double dt = 0;     ///< [s]; 0: 0.9 of the explicit limit, or 1 ms implicit
  double t_end = 1;  ///< [s]
  long frames = 24;  ///< OBJ meshes of the plate
};

/// Adds the flags above, and the common --fail-on-divergence, --quick and --no-viewer.
void add_continuum_flags(ChapterApp& app, ContinuumFlags& flags);

/// What the flags ask for, checked.
struct ContinuumSetup {
  FemMaterial material;
  FemModel model = FemModel::stvk;
  MeshKind mesh = MeshKind::regular;
  TimeIntegrator integrator = TimeIntegrator::explicit_euler;
  int resolution = 8;
  double dt = 0, t_end = 1;  ///< [s]
  long frames = 0;
};
/// Throws UsageError naming the flag when --dt is longer than --t-end.
ContinuumSetup continuum_setup(const ContinuumFlags& flags);

/// The plate's step [s] for these flags before it is built: --dt, or for explicit Euler 0.9 of
/// half a cell over the plane-stress wave speed √(E / (ρ (1 − ν²))) (a bound on the true limit),
/// or 1 ms implicit.
double scene_step(const ContinuumSetup& setup);
/// "--young 1e+09 Pa, --poisson 0.3, …, --frames 24": every flag an estimate depends on.
std::string describe_continuum_run(const ContinuumFlags& flags);

}  // namespace kit
