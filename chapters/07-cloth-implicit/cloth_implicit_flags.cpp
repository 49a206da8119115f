// Chapter 7's command line (cloth_implicit_flags.hpp).
#include "cloth_implicit_flags.hpp"

#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

namespace kit {
namespace {

std::optional<ImplicitMethod> implicit_named(const std::string& name) {
  for (const ImplicitMethod m : all_implicit_methods)
    if (name == flag_name(m)) return m;
  return std::nullopt;
}

}  // namespace

void add_implicit_cloth_flags(ChapterApp& app, ClothFlags& cloth, ImplicitFlags& f) {
  std::vector<std::string> implicit;
  for (const ImplicitMethod m : all_implicit_methods) implicit.emplace_back(flag_name(m));
  cloth.scene = "drape";  // chapter 7's default scene, before --scene records its default
  add_cloth_flags(app, cloth, implicit);
  app.add_divergence_flag();
  app.add_quick_flag("three stiffnesses in the sweep, a trade over 1/3 s, solver curves at h = 1/30 to 1/120 s");
  app.add_choice("--solver", f.solver,
                 "linear solver: cg (Eigen, diagonal preconditioner), pcg (ex 7.3, filtered) or mg "
                 "(filtered, multigrid preconditioner: the fast one)",
                 {"cg", "pcg", "mg"});
  app.add_real("--cg-tol", f.cg_tol, "relative residual of each linear solve", between(1e-14, 0.5));
  app.add_count("--iterations", f.iterations,
                "the scene run's Liu local/global iterations, or Newton's most (the fixed experiments use 10)", 1, 1000);
  app.cli().add_flag("--no-clamp", f.no_clamp,
                     "keep the compressed springs' negative term: A may be indefinite and CG may fail");
}

ClothScene apply_implicit_cloth_flags(ClothScene scene, const ClothFlags& cloth) {
  ClothFlags explicit_only = cloth;
  if (implicit_named(cloth.integrator)) explicit_only.integrator.clear();
  return apply_cloth_flags(std::move(scene), explicit_only);
}

ClothRunOptions implicit_cloth_run(const ClothScene& scene, const ClothFlags& cloth, const ImplicitFlags& f,
                                   ImplicitKernels kernels) {
  ClothRunOptions run = cloth_run_options(scene);
  if (cloth.integrator.empty() || implicit_named(cloth.integrator)) {
    run.implicit = cloth.integrator.empty() ? ImplicitMethod::linearised : *implicit_named(cloth.integrator);
    if (!(cloth.dt > 0)) run.dt = implicit_default_dt;
  }
  for (const ImplicitSolver solver : all_implicit_solvers)
    if (f.solver == flag_name(solver)) run.implicit_settings.solver = solver;
  run.implicit_settings.cg_tolerance = f.cg_tol;
  run.implicit_settings.iterations = int(f.iterations);
  run.implicit_settings.clamp = !f.no_clamp;
  run.implicit_kernels = kernels;
  return run;
}

std::string describe_implicit_run(const ClothScene& scene, const ClothRunOptions& run) {
  return fmt::format("--integrator {}, --dt {:.4g} s, --t-end {} s, --resolution {} ({}×{} nodes), --frames {}",
                     run.implicit ? flag_name(*run.implicit) : flag_name(run.integrator), run.dt, run.t_end,
                     scene.grid.nx, scene.grid.nx, scene.grid.ny, run.frames);
}

}  // namespace kit
