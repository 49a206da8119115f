// Chapter 7: cloth, implicit (lecture, "Schéma implicite"; Baraff & Witkin 1998). Linearised forces
// (ex 7.1), A Δv = b each step (ex 7.2) solved by filtered conjugate gradients (ex 7.3); what it buys
// and costs against chapter 6's explicit methods, Newton's backward Euler and Liu et al. 2013.
#include <filesystem>

#include <fmt/format.h>

#include <kit/app/chapter_app.hpp>

#include "cloth_implicit_estimate.hpp"
#include "cloth_implicit_figures.hpp"
#include "cloth_implicit_flags.hpp"
#include "cloth_implicit_page.hpp"
#include "cloth_implicit_tables.hpp"
#include "cloth_implicit_wiring.hpp"
#include "cloth_kernels.hpp"
#include "cloth_output.hpp"
#include "implicit_kernel_checks.hpp"

namespace {
using kit::ChapterApp, kit::ClothScene, kit::ClothKernels, kit::ImplicitKernels, kit::ImplicitSettings;
using Sizes = kit::ImplicitExperimentSizes;  // of the fixed experiments: the lecture's, or --quick's

// 1. "Linéarisation: f(x_n + Δx, v_n + Δv) = f_n + ∂f/∂x Δx + ∂f/∂v Δv": ex 7.1's block against
//    central differences of the spring force, and what the clamp does to a compressed spring.
void linearisation(ChapterApp& app, ImplicitKernels implicit) {
  kit::say_jacobian_check(app.report(), kit::check_stiffness_block(implicit.stiffness_block));
}

// 2. "Système linéaire à chaque pas de temps: A Δv = b" (ERRATA 14, symmetric form): ex 7.2
//    against the kit's scatter into a pattern built once; ex 7.3 on an indefinite A.
void linear_system(ChapterApp& app, const ClothScene& scene, const kit::Springs& springs,
                   ImplicitKernels implicit, double h) {
  kit::say_assembly_check(app.report(), kit::check_assembly(scene, springs, implicit, h), scene.name, h);
}

// 3. "⇒ grands pas de temps": K from 1e1 to 1e7 N/m, symplectic Euler's largest stable step
//    against the implicit methods at 1/30 s; "linéarisation": one step's error against Newton.
void large_steps(ChapterApp& app, const ClothScene& scene, ClothKernels kernels, ImplicitKernels implicit,
                 const ImplicitSettings& settings, const Sizes& sizes) {
  const auto rows = kit::stiffness_sweep(scene, kernels, implicit, settings, sizes.sweep_k);
  app.report().print("3. The sheet at 8 nodes across, held at two corners, 1 s under gravity, undamped:\n");
  kit::print_stiffness_table(app.report(), rows, 1.0 / 30);
  app.figure(kit::cloth_stiffness_figure(rows, 1.0 / 30, scene.name));
  const kit::Linearisation l = kit::linearisation_error(scene, kernels, implicit, settings, 1.0 / 30);
  if (!l.failure.empty()) return app.report().print("One step mid-swing failed: " + l.failure + ".\n\n");
  app.report().say("linearisation",
                   "One step of h = {h:.4g} s mid-swing (K = 1e4 N/m): the linearised Δv "
                   "differs from backward Euler's exact one by {difference:.2e} (relative); Newton took "
                   "{iterations} solves to a residual of {residual:.1e}.\n\n",
                   {{"h", l.h},
                    {"difference", l.difference},
                    {"iterations", l.newton_iterations},
                    {"residual", l.newton_residual}});
}

// 4. What a large step costs in accuracy: the energy implicit methods remove, and the error
//    against wall time of every method over its range of steps (and of Liu's iterations).
void cost_of_accuracy(ChapterApp& app, const ClothScene& scene, ClothKernels kernels,
                      ImplicitKernels implicit, const ImplicitSettings& settings, const Sizes& sizes) {
  const auto trade = kit::speed_accuracy_trade(scene, kernels, implicit, settings, 10, 1e4, sizes.trade_t);
  app.report().say("trade_reference",
                   "4. The sheet at {n} nodes across, K = {k:.3g} N/m, {t:.3g} s; the "
                   "reference is RK4 at Δt = {dt:.3g} s (its energy drifts {drift:.1e} J); symplectic "
                   "Euler's limit is {dt_max:.3g} s:\n",
                   {{"n", long(trade.n)},
                    {"k", trade.stiffness},
                    {"t", trade.t_end},
                    {"dt", trade.reference_dt},
                    {"drift", trade.reference_energy_drift},
                    {"dt_max", trade.dt_max}});
  kit::print_trade_table(app.report(), trade);
  app.figure(kit::cloth_damping_figure(trade, scene.name));
  app.figure(kit::cloth_trade_figure(trade, scene.name));
}

// 5. The linear solver: CG iterations per solve against h and K: Eigen CG, filtered PCG, multigrid PCG.
void solver_cost(ChapterApp& app, const ClothScene& scene, ClothKernels kernels, ImplicitKernels implicit,
                 const ImplicitSettings& settings, const Sizes& sizes) {
  const auto points = kit::solver_behaviour(scene, kernels, implicit, settings, sizes.cg_k, sizes.cg_h);
  app.report().print(fmt::format("\n5. Conjugate gradients to {:.0e}; the sheet, 12 nodes across, 0.25 s:\n",
                                 settings.cg_tolerance));
  kit::print_solver_table(app.report(), points);
  app.figure(kit::cloth_solver_figure(points, scene.name));
}

// 6. The scene at the chosen method and step: contacts, counts, frames, meshes and animation.
void scene_run(ChapterApp& app, const ClothScene& scene, const kit::Springs& springs, ClothKernels kernels,
               const kit::ClothRunOptions& run, const kit::ClothOutputOptions& output) {
  const kit::ClothRecording rec = kit::run_cloth(scene, springs, kernels, run);
  const std::string method = run.implicit ? kit::flag_name(*run.implicit) : kit::flag_name(run.integrator);
  const std::string why = rec.failure.empty() ? "it exploded" : rec.failure;
  if (rec.exploded_at >= 0) app.diverged(method, fmt::format("at t = {:.4g} s: {}", rec.exploded_at, why));
  app.report().say("run",
                   "\n6. '{scene}' with {method} at h = {dt:.4g} s: {steps} steps, E(end) − E(0) = "
                   "{energy:.3e} J, peak stretch {strain:.3g}%, deepest in a collider {deepest:.2e} m.\n",
                   {{"scene", scene.name},
                    {"method", method},
                    {"dt", run.dt},
                    {"steps", rec.steps},
                    {"energy", rec.samples.back().total() - rec.samples.front().total()},
                    {"strain", 100 * rec.peak_strain},
                    {"deepest", rec.deepest}});
  kit::print_implicit_work(app.report(), rec);
  if (output.dir.empty() || rec.frames.size() < 2) return;
  const kit::ClothOutput made = kit::write_cloth_output(scene, rec, output);
  app.report().say(
      "frames", "{frames} frames and OBJ meshes in {dir}; {movie}\n",
      {{"frames", long(made.frames.size())}, {"dir", output.dir.string()}, {"movie", made.note}});
  for (const auto& file : made.movies) app.summary()["figures"]["animation"].push_back(file.string());
  kit::write_implicit_scene_page(app, scene, springs, kernels, run, rec, output.dir);
}
}  // namespace

int main(int argc, char** argv) {
  kit::ClothFlags flags;  // the scene "drape" unless --scene says otherwise (add_implicit_cloth_flags)
  kit::ImplicitFlags implicit_flags;
  ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 7: cloth, implicit integration");
  kit::add_implicit_cloth_flags(app, flags, implicit_flags);  // --fail-on-divergence and --quick too
  return app.run(argc, argv, [&] {
    const auto scenes = std::filesystem::path(KIT_CHAPTER_SOURCE_DIR) / ".." / "06-cloth-explicit" / "scenes";
    const auto scene = kit::apply_implicit_cloth_flags(kit::load_cloth_scene_flag(flags, scenes), flags);
    const ImplicitKernels implicit = kit::student_implicit_kernels();
    const kit::ClothRunOptions run = kit::implicit_cloth_run(scene, flags, implicit_flags, implicit);
    kit::announce_run(app.report(), "runs", "Chapter 7's scene run", kit::estimate_implicit_run(scene, run),
                      kit::describe_implicit_run(scene, run), {.max_bytes = kit::machine_memory()});
    app.summary()["scene"] = kit::cloth_scene_summary(scene);
    const ClothKernels kernels = kit::student_cloth_kernels();
    const ImplicitSettings& settings = run.implicit_settings;  // the flags' solver, for every section
    const Sizes sizes = Sizes::for_run(app.options().quick);
    app.section("linearisation", [&] { linearisation(app, implicit); });
    const auto springs =
        app.section("the springs", [&] { return kernels.build_springs(scene.grid, scene.springs); });
    app.section("the linear system", [&] {
      if (!springs) throw kit::NotImplemented("ex 6.2", "cloth_springs.hpp");
      linear_system(app, scene, *springs, implicit, run.dt);
    });
    app.section("large steps", {"stiffness"},
                [&] { large_steps(app, scene, kernels, implicit, settings, sizes); });
    app.section("the cost of accuracy", {"damping", "trade-timing"},
                [&] { cost_of_accuracy(app, scene, kernels, implicit, settings, sizes); });
    app.section("the linear solver", {"solver"},
                [&] { solver_cost(app, scene, kernels, implicit, settings, sizes); });
    app.section("the scene", [&] {
      if (!springs) throw kit::NotImplemented("ex 6.2", "cloth_springs.hpp");
      scene_run(app, scene, *springs, kernels, run, kit::cloth_output_options(flags, app.options(), run));
    });
  });
}
