// Chapter 9: continuum mechanics (lecture, "Mécanique des milieux continus"): ∇·σ + F_ext = η ü
// with the Green strain ε = ½(∇u + ∇uᵀ + ∇uᵀ∇u), by linear triangles (ex 9.1 to 9.3). Why Green's
// strain and not the small one; a cantilever against Euler–Bernoulli; the springs' "dépendance au
// maillage"; what accuracy costs; and a spinning plate as OBJ meshes.
#include <map>

#include <fmt/format.h>

#include <kit/app/chapter_app.hpp>

#include "continuum_estimate.hpp"
#include "continuum_figures.hpp"
#include "continuum_flags.hpp"
#include "continuum_report.hpp"
#include "fem_kernels.hpp"
#include "fem_output.hpp"
#include "fem_page.hpp"

namespace {
using kit::ChapterApp, kit::ContinuumKernels, kit::ContinuumSetup, kit::FemModel, kit::TipSolver;

// 1. "σ = E ε": the material, in plane stress (errata 16: Lamé's λ and μ, not one E), and the
//    cantilever's closed forms.
void the_material(ChapterApp& app, const ContinuumSetup& s) { kit::print_material(app.report(), s.material); }

// 2. "ε = ½(∇u + ∇uᵀ + ∇uᵀ∇u)": one element turned rigidly, then a free plate spun at π rad/s for
//    --t-end by each model, with --integrator, --dt, --resolution and --mesh.
void green_strain(ChapterApp& app, const ContinuumSetup& s, const ContinuumKernels& kernels) {
  app.report().attempt("the rigid turn", [&] {
    const auto sweep = kit::turn_sweep(s.material, kernels);
    app.report().print("\n2. One element turned rigidly in its plane (forces relative to a 1% stretch's):\n");
    kit::print_turns(app.report(), sweep);
    app.figure(kit::turn_figure(sweep));
  });
  std::map<FemModel, kit::PlateRun> runs;
  std::map<FemModel, std::vector<kit::TimedOutline>>
      outlines;  // linear and StVK, near t = 0, ⅓, ⅔, 1 of --t-end
  for (const FemModel model : {FemModel::linear, FemModel::stvk, FemModel::springs}) {
    const auto keep_outline = [&](const kit::FemBody& body, int, double t) {
      if (model == FemModel::springs) return;
      auto& kept = outlines[model];
      if (t < s.t_end * double(kept.size()) / 3 * (1 - 1e-9)) return;
      kit::Outline shape;
      for (const int node : kit::boundary_loop(body.mesh()))
        shape.emplace_back(body.x(node, 0), body.x(node, 1));
      kept.emplace_back(t, std::move(shape));
    };
    app.report().attempt(kit::model_name(model), [&] {
      runs[model] = kit::spin_plate(s.material, model, s.integrator, s.resolution, s.mesh, s.dt, s.t_end,
                                    kernels, 90, keep_outline);
      if (runs[model].diverged) app.diverged(fmt::format("spinning plate ({})", kit::model_name(model)), "");
    });
    if (!runs.contains(model)) outlines.erase(model);
  }
  if (runs.empty()) return;
  app.report().print(fmt::format("\nA free {0}×{0} plate spun at π rad/s for {1:g} s ({2} Euler):\n",
                                 s.resolution, s.t_end, kit::integrator_name(s.integrator)));
  kit::print_plate(app.report(), runs);
  app.figure(kit::plate_figure(runs, kit::integrator_name(s.integrator)));
  if (outlines.size() == 2) app.figure(kit::plate_shapes_figure(outlines));
}

// 3. Against a closed form: the cantilever under its own weight, each model at 20 to 20480 elements,
//    against Euler–Bernoulli (and Timoshenko, who lets the beam shear).
void cantilever(ChapterApp& app, const ContinuumSetup& s, const ContinuumKernels& kernels) {
  app.report().print("\n3. The cantilever's tip by mesh, static Newton:\n");
  std::map<FemModel, kit::TipConvergence> models;
  for (const FemModel model : {FemModel::linear, FemModel::stvk, FemModel::springs})
    app.report().attempt(kit::model_name(model),
                         [&] { models[model] = kit::cantilever_convergence(s.material, model, kernels); });
  if (models.empty()) return;
  kit::print_cantilever(app.report(), models, s.material);
  app.figure(kit::cantilever_figure(models, s.material));
}

// 4. "Limitations: dépendance au maillage": a sheet stretched by the same load on regular and
//    irregular meshes, by St Venant–Kirchhoff and by springs.
void mesh_dependence(ChapterApp& app, const ContinuumSetup& s, const ContinuumKernels& kernels) {
  app.report().print(
      "\n4. A 1 m sheet clamped on its left edge, pulled by 1e-3 E on its right edge: its stretch "
      "over the 1-D answer σL/E:\n");
  std::map<FemModel, std::vector<kit::StretchRow>> rows;
  for (const FemModel model : {FemModel::stvk, FemModel::springs})
    app.report().attempt(kit::model_name(model), [&] {
      rows[model] = kit::stretch_sweep(s.material, model, {4, 8, 16, 32, 64}, kernels);
    });
  if (rows.empty()) return;
  kit::print_stretch(app.report(), rows);
  app.figure(kit::stretch_figure(rows));
}

// 5. What accuracy costs: the cantilever's tip error against wall time, springs and linear FEM
//    by Newton, St Venant–Kirchhoff by Newton and by explicit and implicit relaxation (--quick: to 4 high).
void cost_of_accuracy(ChapterApp& app, const ContinuumSetup& s, const ContinuumKernels& kernels) {
  app.report().print("\n5. The cantilever's tip against wall time:\n");
  const std::vector<std::pair<FemModel, TipSolver>> methods{{FemModel::springs, TipSolver::newton},
                                                            {FemModel::linear, TipSolver::newton},
                                                            {FemModel::stvk, TipSolver::newton},
                                                            {FemModel::stvk, TipSolver::explicit_relaxation},
                                                            {FemModel::stvk, TipSolver::implicit_relaxation}};
  std::vector<std::vector<kit::TipRun>> series;
  for (const auto& method : methods)  // not a structured binding: a lambda may not capture one before C++23
    app.report().attempt(
        fmt::format("{}, {}", kit::model_name(method.first), kit::solver_name(method.second)), [&] {
          std::vector<kit::TipRun> list;
          for (const int ny : app.options().quick ? std::vector{1, 2, 4} : std::vector{1, 2, 4, 8})
            list.push_back(kit::run_cantilever(s.material, method.first, method.second, ny, kernels));
          series.push_back(list);
        });
  if (series.empty()) return;
  kit::print_trade(app.report(), series);
  app.figure(kit::trade_figure(series));
}

// 6. The scene: the plate by --model for --t-end, as --frames OBJ meshes (the first at t = 0).
void scene(ChapterApp& app, const ContinuumSetup& s, const ContinuumKernels& kernels) {
  kit::plate_scene(app, s, kernels);
}
}  // namespace

int main(int argc, char** argv) {
  kit::ContinuumFlags flags;
  ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 9: continuum mechanics");
  kit::add_continuum_flags(app, flags);  // --fail-on-divergence, --quick and --no-viewer too
  return app.run(argc, argv, [&] {
    const ContinuumSetup setup = kit::continuum_setup(flags);
    kit::announce_run(app.report(), "runs", "Chapter 9", kit::estimate_continuum_runs(setup),
                      kit::describe_continuum_run(flags), {.max_bytes = kit::machine_memory()});
    const ContinuumKernels kernels = kit::student_continuum_kernels();
    app.section("the material", [&] { the_material(app, setup); });
    app.section("green strain", {"turned-element", "spinning-plate", "plate-shapes"},
                [&] { green_strain(app, setup, kernels); });
    app.section("the cantilever", {"cantilever"}, [&] { cantilever(app, setup, kernels); });
    app.section("mesh dependence", {"mesh-dependence"}, [&] { mesh_dependence(app, setup, kernels); });
    app.section("the cost of accuracy", {"trade-timing"}, [&] { cost_of_accuracy(app, setup, kernels); });
    app.section("the scene", [&] { scene(app, setup, kernels); });
  });
}
