// Chapter 6: cloth with explicit integration (lecture, "Simulation de tissus"). A sheet is a grid
// of nodes joined by springs (ex 6.1 the force, ex 6.2 the network); the lecture's loop steps it
// (ex 6.3, symplectic Euler) and the cloth meets colliders (ex 6.4). The chapter measures the
// largest stable step against its prediction, the cost of resolution, energy and the
// super-elastic effect, writes frames and meshes, and shows the mesh dependence of springs.
#include <filesystem>

#include <fmt/format.h>

#include <kit/app/chapter_app.hpp>
#include <kit/cloth/cloth_estimate.hpp>

#include "cloth_figures.hpp"
#include "cloth_flags.hpp"
#include "cloth_kernels.hpp"
#include "cloth_output.hpp"
#include "cloth_page.hpp"
#include "cloth_report.hpp"
#include "cloth_spring_force.hpp"
#include "cloth_tables.hpp"
#include "spring_force_check.hpp"

namespace {
namespace fs = std::filesystem;
using kit::ChapterApp, kit::ClothScene, kit::ClothKernels, kit::ClothIntegrator, kit::ClothRecording;

// 1. "En 3D: F = K (L0 − |x − x0|) (x − x0)/|x − x0|": ex 6.1 on random springs.
void spring_in_3d(ChapterApp& app) {
  const kit::SpringForceCheck c = kit::check_spring_force(&kit::spring_force);
  kit::say_spring_force_check(app.report(), c);
}

// 2. "Ressorts couplés: structural, shear, bend": ex 6.2 builds the scene's network.
kit::Springs coupled_springs(ChapterApp& app, const ClothScene& scene, ClothKernels kernels) {
  kit::Springs springs = kernels.build_springs(scene.grid, scene.springs);
  kit::say_coupled_springs(app.report(), scene, springs);
  return springs;
}

// 3. "⇒ Schéma d'intégration favori": the largest stable Δt, measured by bisection, against
//    c/ω_max (c = 2 for symplectic Euler, 2√2 for RK4, ω_max² = λ_max(M⁻¹K) at rest by power
//    iteration); then how it falls, and the cost grows, with resolution (--quick: 8 across, to 32).
void favourite_scheme(ChapterApp& app, const ClothScene& scene, ClothKernels kernels) {
  const bool quick = app.options().quick;
  const auto cases = kit::stability_cases(scene, quick ? 8 : 16, kernels, 1e-4);
  app.report().print(
      fmt::format("3. The largest stable step at {} nodes across, every spring at the structural K. "
                  "Stable: no mode grows. Undamped, explicit Euler and midpoint grow at every Δt; damped "
                  "along the springs (μ = τK), explicit Euler holds for Δt < τ while every mode is "
                  "underdamped:\n",
                  quick ? 8 : 16));
  kit::print_stability_table(app.report(), cases);
  app.figure(kit::cloth_stability_figure(cases, scene.name));
  std::vector<kit::StabilityAtResolution> sweep;
  for (int n : quick ? std::vector{16, 32} : std::vector{16, 32, 64})
    sweep.push_back(kit::stability_at(scene, n, kernels, ClothIntegrator::symplectic_euler));
  app.report().print("\nSymplectic Euler, the scene's springs undamped, the sheet at N nodes across:\n");
  kit::print_resolution_table(app.report(), sweep);
  app.figure(kit::cloth_resolution_figure(sweep, scene.name));
}

// 4. "Algorithme Euler explicite" (ERRATA 7: the loop is symplectic Euler): each integrator on
//    the scene at its Δt; energy drift, explosions, and what was computed.
kit::ClothRuns explicit_loop(ChapterApp& app, const ClothScene& scene, const kit::Springs& springs,
                             ClothKernels kernels, const kit::ClothRunOptions& run) {
  const kit::ClothRuns runs = kit::run_each_integrator(scene, springs, kernels, run);
  for (const auto& [integrator, rec] : runs)
    if (rec.exploded_at >= 0)
      app.diverged(kit::flag_name(integrator), fmt::format("it exploded at t = {:.4g} s", rec.exploded_at));
  app.report().print(fmt::format("4. '{}', {} s at Δt = {:.3g} s:\n", scene.name, run.t_end, run.dt));
  kit::print_integrator_table(app.report(), runs);
  app.figure(kit::cloth_energy_figure(runs, run.dt, scene.name));
  return runs;
}

// 5. The super-elastic effect: springs alone stretch far beyond what cloth does; Provot's limit.
void super_elastic(ChapterApp& app, const ClothScene& scene, const kit::Springs& springs,
                   ClothKernels kernels, const kit::ClothRunOptions& run, const ClothRecording& as_run) {
  const auto c = kit::compare_strain_limit(scene, springs, kernels, run, as_run);
  kit::say_strain_limit(app.report(), c);
  app.figure(kit::cloth_strain_figure(c.free, c.limited, c.max_strain, scene.name));
}

// 6. "Vêtement = Tissu + collisions": the chosen run's contacts, frames, meshes, animation and 3D pages.
void garment(ChapterApp& app, const ClothScene& scene, ClothKernels kernels, const ClothRecording& rec,
             const kit::ClothRunOptions& run, const kit::ClothOutputOptions& output) {
  app.report().say("contacts",
                   "6. Contacts: {tests} node tests, {contacts} nodes pushed out; the deepest a "
                   "node sat inside a collider after a step: {deepest:.2e} m.\n",
                   {{"tests", rec.work.sphere_tests + rec.work.ground_tests},
                    {"contacts", rec.work.contacts},
                    {"deepest", rec.deepest}});
  if (output.dir.empty()) return;
  const kit::ClothOutput made = kit::write_cloth_output(scene, rec, output);
  app.report().say(
      "frames", "{frames} frames and OBJ meshes in {dir}; {movie}\n",
      {{"frames", long(made.frames.size())}, {"dir", output.dir.string()}, {"movie", made.note}});
  for (const auto& file : made.movies) app.summary()["figures"]["animation"].push_back(file.string());
  kit::write_cloth_page(app, "Chapter 6", scene, rec, run, output.dir);
  kit::write_stability_page(app, scene, kernels, run, output.dir);
  if (app.options().show) app.report().print(kit::show_player(made.player) + "\n");
}

// 7. "Limitations: dépendance au maillage": one sheet at rest at N = 8 … 64 (--quick: 32), held four ways.
void mesh_dependence(ChapterApp& app, ClothKernels kernels) {
  const kit::MeshDependence m = kit::measure_mesh_dependence(kernels, app.options().quick ? 32 : 64);
  app.report().print("7. A 1 m sheet at rest, 0.2 kg/m², structural and shear springs of 50 N/m:\n");
  kit::print_mesh_table(app.report(), m.sags);
  const kit::Convergence& c = m.top_edge;
  app.report().say("mesh_limit",
                   "Top edge, same k: the drop {verdict}. With square cells a spring's K [N/m] "
                   "is the sheet's stretch modulus; point pins have no limit.\n",
                   {{"verdict", kit::describe(c, m.finest, 1e3, "mm")},
                    {"order", c.order},
                    {"limit", 1e3 * c.limit},
                    {"remaining", 100 * c.remaining},
                    {"converges", c.converges}});
  app.figure(kit::cloth_mesh_figure(m.sags, m.top_edge.limit));
}
}  // namespace

int main(int argc, char** argv) {
  kit::ClothFlags flags;
  ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 6: cloth, explicit integration");
  kit::add_cloth_flags(app, flags);
  app.add_divergence_flag();
  app.add_quick_flag("the stability table at 8 nodes across, the resolution and mesh sweeps to N = 32");
  return app.run(argc, argv, [&] {
    const fs::path scenes = fs::path(KIT_CHAPTER_SOURCE_DIR) / "scenes";
    const auto scene = kit::apply_cloth_flags(kit::load_cloth_scene_flag(flags, scenes), flags);
    const kit::ClothRunOptions run = kit::cloth_run_options(scene);
    kit::announce_run(app.report(), "runs", "Chapter 6", kit::estimate_cloth_chapter(scene, run),
                      kit::describe_cloth_flags(scene), {.max_bytes = kit::machine_memory()});
    app.summary()["scene"] = kit::cloth_scene_summary(scene);
    const ClothKernels kernels = kit::student_cloth_kernels();
    app.section("the spring in 3-D", [&] { spring_in_3d(app); });
    const auto springs = app.section("coupled springs", [&] { return coupled_springs(app, scene, kernels); });
    app.section("the favourite scheme", {"stability", "resolution"},
                [&] { favourite_scheme(app, scene, kernels); });
    app.section("the explicit loop", {"energy", "strain"}, [&] {
      if (!springs) throw kit::NotImplemented("ex 6.2", "cloth_springs.hpp");
      const auto runs = explicit_loop(app, scene, *springs, kernels, run);
      super_elastic(app, scene, *springs, kernels, run, runs.at(run.integrator));
      garment(app, scene, kernels, runs.at(run.integrator), run,
              kit::cloth_output_options(flags, app.options(), run));
    });
    app.section("mesh dependence", {"mesh"}, [&] { mesh_dependence(app, kernels); });
  });
}
