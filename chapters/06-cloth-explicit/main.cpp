// Chapter 6: cloth with explicit integration (lecture, "Simulation de tissus"). A sheet is a grid
// of nodes joined by springs (ex 6.1 the force, ex 6.2 the network); the lecture's loop steps it
// (ex 6.3, symplectic Euler) and the cloth meets colliders (ex 6.4). The chapter measures the
// largest stable step against its prediction, the cost of resolution, energy and the
// super-elastic effect, writes frames and meshes, and shows the mesh dependence of springs.
#include <filesystem>

#include <fmt/format.h>

#include <kit/chapter_app.hpp>
#include <kit/cloth_figures.hpp>
#include <kit/cloth_flags.hpp>
#include <kit/animation.hpp>
#include <kit/cloth_output.hpp>
#include <kit/spring_force_check.hpp>

#include "cloth_kernels.hpp"
#include "cloth_spring_force.hpp"

namespace {
namespace fs = std::filesystem;

// 1. "En 3D: F = K (L0 − |x − x0|) (x − x0)/|x − x0|": ex 6.1 on random springs.
void spring_in_3d(kit::ChapterApp& app) {
  const kit::SpringForceCheck c = kit::check_spring_force(&kit::spring_force);
  app.report().say("spring", "1. Your spring force on {n} random springs: F_a + F_b = {third:.1e} |F| "
                   "(Newton's third law), F + ∇E = {gradient:.1e} |F| (the force derives from ½K(l − L0)²), "
                   "a pair moving together is damped by {rigid:.1e} μ|v|, a stretch rate w by μw to {stretch:.1e}.\n\n",
                   {{"n", long(c.springs)}, {"third", c.third_law}, {"gradient", c.energy_gradient},
                    {"rigid", c.rigid_damping}, {"stretch", c.stretch_damping}});
}

// 2. "Ressorts couplés: structural, shear, bend": ex 6.2 builds the scene's network; the stiffest
//    mode at rest, ω_max² = λ_max(M⁻¹K), gives symplectic Euler's limit Δt < 2/ω_max.
kit::Springs coupled_springs(kit::ChapterApp& app, const kit::ClothScene& scene, kit::ClothKernels kernels) {
  kit::Springs springs = kernels.build_springs(scene.grid, scene.springs);
  auto table = app.report().table("springs", {{"family", "family"}, {"springs", "count"}, {"expected", "expected"}});
  for (kit::SpringKind kind : kit::all_spring_kinds) {
    kit::SpringLayout only;
    if (scene.springs.family(kind)) (kind == kit::SpringKind::structural ? only.structural : kind == kit::SpringKind::shear ? only.shear : only.bend) = scene.springs.family(kind);
    only.bend_layout = scene.springs.bend_layout;
    table.row({kit::spring_kind_name(kind), springs.count(kind), kit::spring_count(scene.grid.nx, scene.grid.ny, only)});
  }
  app.report().print(fmt::format("2. '{}': {}×{} nodes, {} springs (bend layout: {} neighbours):\n", scene.name,
                                 scene.grid.nx, scene.grid.ny, springs.size(),
                                 scene.springs.bend_layout == kit::BendLayout::four ? 4 : 8));
  table.print();
  return springs;
}

// 3. "⇒ Schéma d'intégration favori": the largest stable Δt, measured by bisection, against
//    c/ω_max (c = 2 for symplectic Euler, 2√2 for RK4); then how it falls with resolution.
void favourite_scheme(kit::ChapterApp& app, const kit::ClothScene& scene, kit::ClothKernels kernels) {
  const auto cases = kit::stability_cases(scene, 16, kernels, 1e-4);
  app.report().print("3. The largest stable step at 16 nodes across, every spring at the structural K; "
                     "stable = no mode grows (without damping explicit Euler and midpoint grow at every Δt):\n");
  auto table = app.report().table("stability", {{"springs", "layout"}, {"integrator", "integrator"},
      {"ω_max [rad/s]", "omega_max", "{:.5g}"}, {"predicted [s]", "predicted", "{:.4e}"},
      {"measured [s]", "measured", "{:.4e}"}, {"measured/predicted", "ratio", "{:.4f}"}});
  for (const auto& c : cases)
    table.row({c.layout, kit::flag_name(c.integrator), c.result.omega_max, c.result.predicted,
               c.result.measured.estimate(), c.result.predicted > 0 ? kit::ReportValue(c.result.measured.estimate() / c.result.predicted) : kit::ReportValue{}});
  table.print();
  app.figure(kit::cloth_stability_figure(cases, scene.name));
  std::vector<kit::StabilityAtResolution> sweep;
  auto law = app.report().table("resolution", {{"N", "n"}, {"springs", "springs"}, {"Δt_max [s]", "dt_max", "{:.4e}"},
      {"N·Δt_max [s]", "n_dt", "{:.4e}"}, {"spring forces per simulated s", "per_second", "{:.3e}"}});
  for (int n : {16, 32, 64}) {
    const auto& r = sweep.emplace_back(kit::stability_at(scene, n, kernels, kit::ClothIntegrator::symplectic_euler));
    law.row({long(n), r.springs, r.measured.estimate(), n * r.measured.estimate(), r.spring_evaluations_per_second});
  }
  app.report().print("\nSymplectic Euler on the scene's own springs as N grows (the same physical sheet):\n");
  law.print();
  app.figure(kit::cloth_resolution_figure(sweep, scene.name));
}

// 4. "Algorithme Euler explicite" (ERRATA 7: the loop is symplectic Euler): each integrator on
//    the scene at its Δt; energy drift, explosions, and what was computed.
std::map<kit::ClothIntegrator, kit::ClothRecording> explicit_loop(kit::ChapterApp& app, const kit::ClothScene& scene,
    const kit::Springs& springs, kit::ClothKernels kernels, const kit::ClothRunOptions& run) {
  std::map<kit::ClothIntegrator, kit::ClothRecording> runs;
  auto table = app.report().table("integrators", {{"integrator", "integrator"}, {"steps", "steps"},
      {"spring forces", "spring_terms"}, {"E(end) − E(0) [J]", "energy_change", "{:.4g}"},
      {"peak stretch [%]", "peak_strain", "{:.3g}"}, {"exploded at [s]", "exploded_at", "{:.4g}"}});
  for (kit::ClothIntegrator integrator : kit::all_cloth_integrators) {
    kit::ClothRunOptions options = run;
    options.integrator = integrator;
    if (integrator != run.integrator) options.frames = 0;
    const auto& rec = runs[integrator] = kit::run_cloth(scene, springs, kernels, options);
    table.row({kit::flag_name(integrator), rec.steps, rec.work.spring_terms,
               rec.samples.back().total() - rec.samples.front().total(), 100 * rec.peak_strain,
               rec.exploded_at >= 0 ? kit::ReportValue(rec.exploded_at) : kit::ReportValue{}});
    if (rec.exploded_at >= 0)
      app.diverged(kit::flag_name(integrator), fmt::format("the cloth exploded at t = {:.4g} s", rec.exploded_at));
  }
  app.report().print(fmt::format("4. '{}' for {} s at Δt = {:.3g} s with each integrator:\n", scene.name, run.t_end, run.dt));
  table.print();
  app.figure(kit::cloth_energy_figure(runs, run.dt, scene.name));
  return runs;
}

// 5. The super-elastic effect: springs alone stretch far beyond what cloth does; Provot's limit.
void super_elastic(kit::ChapterApp& app, const kit::ClothScene& scene, const kit::Springs& springs,
                   kit::ClothKernels kernels, kit::ClothRunOptions run, const kit::ClothRecording& as_run) {
  run.frames = 0;
  kit::ClothScene limited = scene;
  if (!limited.strain_limit) limited.strain_limit = kit::StrainLimit{};
  run.strain_limit = !scene.strain_limit;
  const auto other = kit::run_cloth(limited, springs, kernels, run);
  const auto& [free, with_limit] = scene.strain_limit ? std::tie(other, as_run) : std::tie(as_run, other);
  app.report().say("strain", "5. Peak stretch {free:.3g}% with springs alone, {limited:.3g}% with Provot's limit "
                   "of {max:.3g}% ({passes} passes, {fixes} springs pulled back).\n",
                   {{"free", 100 * free.peak_strain}, {"limited", 100 * with_limit.peak_strain},
                    {"max", 100 * limited.strain_limit->max_strain}, {"passes", with_limit.work.strain_passes},
                    {"fixes", with_limit.work.strain_corrections}});
  app.figure(kit::cloth_strain_figure(free, with_limit, limited.strain_limit->max_strain, scene.name));
}

// 6. "Vêtement = Tissu + collisions": the chosen run's contacts, its frames, meshes and animation.
void garment(kit::ChapterApp& app, const kit::ClothScene& scene, const kit::ClothRecording& rec,
             const kit::ClothOutputOptions& output) {
  app.report().say("contacts", "6. Contacts: {tests} node tests, {contacts} nodes pushed out; the deepest a node "
                   "sat inside a collider after a step: {deepest:.2e} m.\n", {{"tests", rec.work.sphere_tests +
                   rec.work.ground_tests}, {"contacts", rec.work.contacts}, {"deepest", rec.deepest}});
  if (output.dir.empty()) return;
  const kit::ClothOutput made = kit::write_cloth_output(scene, rec, output);
  app.report().say("frames", "{frames} frames and {meshes} OBJ meshes in {dir}; {movie}\n",
                   {{"frames", long(made.frames.size())}, {"meshes", long(made.meshes.size())},
                    {"dir", output.dir.string()}, {"movie", made.note}});
  for (const auto& file : made.movies) app.summary()["figures"]["animation"].push_back(file.string());
  if (app.options().show) app.report().print(kit::show_player(made.player) + "\n");
}

// 7. "Limitations: dépendance au maillage": one sheet at rest at N = 8 … 64, held four ways.
void mesh_dependence(kit::ChapterApp& app, kit::ClothKernels kernels) {
  std::map<kit::Hanging, std::vector<kit::Sag>> sags;
  auto table = app.report().table("mesh", {{"held", "hanging"}, {"N", "n"}, {"drop [mm]", "drop_mm", "{:.3f}"},
                                          {"peak stretch [%]", "peak_strain", "{:.3g}"}, {"steps", "steps"}});
  for (kit::Hanging hanging : kit::all_hangings)
    for (int n : {8, 16, 32, 64}) {
      const kit::Sag& s = sags[hanging].emplace_back(kit::hanging_sag(n, hanging, kernels));
      table.row({kit::describe(hanging), long(n), 1e3 * s.drop, 100 * s.peak_strain, s.steps});
    }
  app.report().print("7. A 1 m sheet hanging at rest, 0.2 kg/m², structural and shear springs of 50 N/m:\n");
  table.print();
  const auto drop = [&](kit::Hanging h, int k) { return sags[h][std::size_t(k)].drop; };
  const kit::Convergence edge = kit::richardson(drop(kit::Hanging::top_edge, 1), drop(kit::Hanging::top_edge, 2),
                                                drop(kit::Hanging::top_edge, 3));
  app.report().say("mesh_limit", "Top edge, same k: the drop converges at order {order:.2f} to {limit:.4f} mm, "
                   "{remaining:.2g}% away at N = 64: in 2-D a spring's k [N/m] is already the sheet's stretch "
                   "modulus when cells are square.\n", {{"order", edge.order}, {"limit", 1e3 * edge.limit},
                   {"remaining", 100 * edge.remaining}});
  app.figure(kit::cloth_mesh_figure(sags, edge.limit));
}
}  // namespace

int main(int argc, char** argv) {
  kit::ClothFlags flags;
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 6: cloth, explicit integration");
  kit::add_cloth_flags(app, flags);
  app.add_divergence_flag();
  return app.run(argc, argv, [&] {
    const auto scene = kit::apply_cloth_flags(kit::load_cloth_scene_flag(flags, fs::path(KIT_CHAPTER_SOURCE_DIR) / "scenes"), flags);
    const kit::ClothRunOptions run = kit::cloth_run_options(scene);
    kit::announce_run(app.report(), "animation", "The run", kit::estimate_cloth_chapter(scene, run),
                      kit::describe_cloth_flags(scene), {.max_bytes = kit::machine_memory()});
    app.summary()["scene"] = kit::cloth_scene_summary(scene);
    const kit::ClothKernels kernels = kit::student_cloth_kernels();
    app.section("the spring in 3-D", [&] { spring_in_3d(app); });
    const auto springs = app.section("coupled springs", [&] { return coupled_springs(app, scene, kernels); });
    app.section("the favourite scheme", [&] { favourite_scheme(app, scene, kernels); });
    if (!springs) return;
    app.section("the explicit loop", [&] {
      const auto runs = explicit_loop(app, scene, *springs, kernels, run);
      super_elastic(app, scene, *springs, kernels, run, runs.at(run.integrator));
      garment(app, scene, runs.at(run.integrator), kit::cloth_output_options(flags, app.options(), run));
    });
    app.section("mesh dependence", [&] { mesh_dependence(app, kernels); });
  });
}
