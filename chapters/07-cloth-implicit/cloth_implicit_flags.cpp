// Chapter 7's command line (cloth_implicit_flags.hpp).
#include "cloth_implicit_flags.hpp"

#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

namespace kit {

void add_implicit_cloth_flags(ChapterApp& app, ClothFlags& cloth, ImplicitFlags& f) {
  const std::vector<std::string> implicit = implicit_method_names.flags();
  cloth.scene = "drape";  // chapter 7's default scene, before --scene records its default
  add_cloth_flags(app, cloth, implicit);
  app.add_divergence_flag();
  app.add_quick_flag(
      "three stiffnesses in the sweep, a trade over 1/3 s, solver curves at h = 1/30 to 1/120 s");
  app.add_choice("--solver", f.solver,
                 "linear solver: cg (Eigen, diagonal preconditioner), pcg (ex 7.3, filtered) or mg "
                 "(filtered, multigrid preconditioner: the fast one)",
                 implicit_solver_names.flags());
  app.add_real("--cg-tol", f.cg_tol, "relative residual of each linear solve", between(1e-14, 0.5));
  app.add_count(
      "--iterations", f.iterations,
      "the scene run's Liu local/global iterations, or Newton's most (the fixed experiments use 10)", 1,
      1000);
  app.cli().add_flag("--no-clamp", f.no_clamp,
                     "keep the compressed springs' negative term: A may be indefinite and CG may fail");
}

ClothScene apply_implicit_cloth_flags(ClothScene scene, const ClothFlags& cloth) {
  ClothFlags explicit_only = cloth;
  if (implicit_method_names.parse(cloth.integrator)) explicit_only.integrator.clear();
  return apply_cloth_flags(std::move(scene), explicit_only);
}

ClothRunOptions implicit_cloth_run(const ClothScene& scene, const ClothFlags& cloth, const ImplicitFlags& f,
                                   ImplicitKernels kernels) {
  ClothRunOptions run = cloth_run_options(scene);
  if (const auto implicit = implicit_method_names.parse(cloth.integrator);
      cloth.integrator.empty() || implicit) {
    run.implicit = implicit.value_or(ImplicitMethod::linearised);
    if (!(cloth.dt > 0)) run.dt = implicit_default_dt;
  }
  run.implicit_settings.solver = implicit_solver_names.parse(f.solver).value_or(run.implicit_settings.solver);
  run.implicit_settings.cg_tolerance = f.cg_tol;
  run.implicit_settings.iterations = int(f.iterations);
  run.implicit_settings.clamp = !f.no_clamp;
  run.implicit_kernels = kernels;
  return run;
}

std::string describe_implicit_run(const ClothScene& scene, const ClothRunOptions& run) {
  return fmt::format(
      "--integrator {}, --dt {:.4g} s, --t-end {} s, --resolution {} ({}×{} nodes), --frames {}",
      run.implicit ? flag_name(*run.implicit) : flag_name(run.integrator), run.dt, run.t_end, scene.grid.nx,
      scene.grid.nx, scene.grid.ny, run.frames);
}

}  // namespace kit
