// Chapter 8: rigid bodies (lecture, "Mécanique du solide"). The state (x, R, P, L) and
// d/dt (x, R, P, L) = (v, ω* R, F, τ); the lecture's steps (ex 8.1 to 8.4) against the kit's on the
// tumbling T-handle, whose spin about its intermediate axis flips (the Dzhanibekov effect); then
// "− collisions": a box dropped on the ground.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <kit/app/chapter_app.hpp>
#include <kit/rigid/rigid_renderer.hpp>

#include "rigid_estimate.hpp"
#include "rigid_figures.hpp"
#include "rigid_flags.hpp"
#include "rigid_kernels.hpp"
#include "rigid_output.hpp"
#include "rigid_page.hpp"
#include "rigid_report.hpp"

namespace {
using kit::ChapterApp, kit::RigidKernels, kit::RigidSetup, kit::RigidState, kit::RotationIntegrator;
using Integrators = std::vector<RotationIntegrator>;

// 1. "ω(t) = I(t)⁻¹ L(t), I(t) = R I_body Rᵀ": the body and the closed form of its torque-free
//    motion (Landau & Lifshitz §37); ex 8.3 against the inverse of the world inertia.
void the_body(ChapterApp& app, const RigidSetup& s, const RigidKernels& kernels, const RigidState& start) {
  kit::print_body(app.report(), s.shape, s.omega0, kit::closed_form_flip_interval(s.shape, start));
  app.report().attempt("ω from L (ex 8.3)",
                       [&] { kit::print_angular_velocity_check(app.report(), kernels, s.shape); });
  app.report().print("\n");
}

// 2. "d/dt R = ω* R": every integrator on the torque-free body at --dt for --t-end; the flips, the
//    drift of E and |L|, and how far R leaves the rotations.
void side_by_side(ChapterApp& app, const RigidSetup& s, const RigidKernels& kernels,
                  const Integrators& integrators, const RigidState& start) {
  std::vector<kit::RotationRun> runs;
  for (RotationIntegrator i : integrators)
    runs.push_back(kit::run_free_rotation(kernels, i, s.shape, start, s.dt, s.t_end));
  const auto flips = kit::reference_flip_times(s.shape, start, s.t_end);
  const double interval = kit::closed_form_flip_interval(s.shape, start);
  app.report().say("reference", "2. {t:g} s at h = {h:.3g} s; GSL rk8pd at 1e-13 flips {flips} times:\n",
                   {{"t", s.t_end}, {"h", s.dt}, {"flips", long(flips.size())}});
  kit::print_drift_table(app.report(), runs, interval);
  for (const auto& run : runs)
    if (run.diverged_at >= 0)
      app.diverged(flag_name(run.integrator), fmt::format("at t = {:.4g} s", run.diverged_at));
  app.figure(kit::rigid_flips_figure(runs, s.shape, flips));
  app.figure(kit::rigid_drift_figure(runs, s.shape.name));
  app.figure(kit::rigid_orthonormality_figure(runs, s.shape.name));
}

// 3. Stability at the extremes: the three principal axes (only the intermediate one flips), and
//    the step at which each integrator stops flipping at the right rate.
void stability(ChapterApp& app, const RigidSetup& s, const RigidKernels& kernels,
               const Integrators& integrators, const RigidState& start) {
  app.report().print("\n3. Spun about each principal axis, nudged by 1%:\n");
  const auto spins = kit::spins_about_axes(s.shape);
  kit::print_axes(app.report(), spins, kit::intermediate_axis(s.shape));
  app.figure(kit::rigid_axes_figure(spins, s.shape.name));
  app.report().print(fmt::format("\nThe flips against the step, {:g} s:\n", s.t_end));
  kit::print_flip_sweep(
      app.report(), kit::flip_sweep(kernels, integrators, s.shape, start, s.t_end, {1e-4, 1e-3, 1e-2, 3e-2}),
      kit::closed_form_flip_interval(s.shape, start));
}

// 4. What accuracy costs: the error in R after 2 s against wall time, each integrator over 100 to
//    --trade-steps steps (default 1e6).
void cost_of_accuracy(ChapterApp& app, const RigidSetup& s, const RigidKernels& kernels,
                      const Integrators& integrators, const RigidState& start) {
  const auto trade = kit::rotation_trade(kernels, integrators, s.shape, start, 2.0, s.trade_steps);
  app.report().say("trade_reference",
                   "\n4. The orientation after {t:g} s against GSL rk8pd at 1e-13 ({evals} "
                   "evaluations):\n",
                   {{"t", trade.t_end}, {"evals", trade.reference_evaluations}});
  kit::print_trade(app.report(), trade);
  app.figure(kit::rigid_trade_figure(trade, s.shape.name));
}

// 5. "− collisions": a box dropped flat and tilted by 30° from 1 m, by impulses at its corners, for 6 s.
void collisions(ChapterApp& app, const RigidSetup& s, const RigidKernels& kernels) {
  const auto box = kit::shape_named("box");
  app.report().print("\n5. A box dropped from 1 m, rotation by the implicit midpoint, h = 1 ms:\n");
  for (const auto& [name, tilt] : {std::pair{"drop", 0.0}, std::pair{"drop_tilted", kit::drop_tilt_deg}}) {
    const std::string what = tilt == 0 ? "flat" : fmt::format("tilted {:g}°", tilt);
    const kit::DropRun run =
        kit::run_drop(kernels, RotationIntegrator::midpoint, box,
                      kit::dropped_state(box, kit::drop_height, tilt), s.contact, 1e-3, 6.0, 0);
    const double resting = kit::resting_height(box, kit::Mat3::Identity());
    kit::print_drop(app.report(), name, what, run, s.contact, kit::drop_height, resting);
    app.figure(kit::rigid_drop_figure(name, "A box dropped " + what, run, s.contact, kit::drop_height));
  }
}

// 6. The scene runs at --integrator and --dt: the body tumbling for --t-end, the box dropped tilted;
//    their frames, OBJ meshes and animations.
void scene_runs(ChapterApp& app, const RigidSetup& s, const RigidKernels& kernels,
                const Integrators& integrators, const RigidState& start) {
  const auto box = kit::shape_named("box");
  const auto tumble =
      kit::run_free_rotation(kernels, s.integrator, s.shape, start, s.dt, s.t_end, 2, s.frames);
  const auto tilted = kit::dropped_state(box, kit::drop_height, kit::drop_tilt_deg);
  const auto drop =
      kit::run_drop(kernels, s.integrator, box, tilted, s.contact, s.dt, kit::scene_drop_seconds, s.frames);
  for (const auto& [what, at] :
       {std::pair{"tumbling", tumble.diverged_at}, std::pair{"dropped", drop.diverged_at}})
    if (at >= 0)
      app.diverged(fmt::format("{} ({})", what, kit::flag_name(s.integrator)),
                   fmt::format("at t = {:.4g} s", at));
  kit::print_scene_runs(app.report(), s.integrator, s.dt, s.shape, s.t_end, tumble, drop);
  if (app.options().no_plot || s.frames == 0) return;
  for (const auto& [stem, shape, frames, seconds] :
       {std::tuple{s.shape.name, s.shape, tumble.frames, s.t_end},
        std::tuple{std::string("drop"), box, drop.frames, kit::scene_drop_seconds}}) {
    const double fps = double(std::max<std::size_t>(frames.size(), 2) - 1) / seconds;  // one frame: still > 0
    const auto made = kit::write_rigid_output(shape, frames, kit::rigid_camera(shape, frames, stem == "drop"),
                                              {app.options().out_dir, 640, 480, fps, stem});
    app.report().say("frames_" + stem, "{frames} frames and OBJ meshes of the {stem} run in {dir}; {movie}\n",
                     {{"frames", long(made.frames.size())},
                      {"stem", stem},
                      {"dir", app.options().out_dir},
                      {"movie", made.note}});
    for (const auto& file : made.movies) app.summary()["figures"]["animation"].push_back(file.string());
  }
  kit::write_rigid_pages(app, s, kernels, integrators, start, drop, kit::scene_drop_seconds);
}
}  // namespace

int main(int argc, char** argv) {
  kit::RigidFlags flags;
  ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 8: rigid bodies");
  kit::add_rigid_flags(app, flags);
  return app.run(argc, argv, [&] {
    const RigidSetup setup = kit::rigid_setup(flags);
    const RigidState start = kit::spinning_state(setup.shape, kit::Vec3(0, 1, 0), setup.omega0);
    kit::announce_run(app.report(), "runs", "Chapter 8", kit::estimate_rigid_runs(setup),
                      kit::describe_rigid_run(flags), {.max_bytes = kit::machine_memory()});
    const RigidKernels kernels = kit::student_rigid_kernels();
    app.section("the body", [&] { the_body(app, setup, kernels, start); });
    const auto integrators = kit::available_rotation_integrators(app.report(), kernels, setup.shape);
    app.section("the integrators", {"flips", "drift", "orthonormality"},
                [&] { side_by_side(app, setup, kernels, integrators, start); });
    app.section("stability", {"axes"}, [&] { stability(app, setup, kernels, integrators, start); });
    app.section("the cost of accuracy", {"trade-timing"},
                [&] { cost_of_accuracy(app, setup, kernels, integrators, start); });
    app.section("collisions", {"drop", "drop_tilted"}, [&] { collisions(app, setup, kernels); });
    app.section("the scene", [&] { scene_runs(app, setup, kernels, integrators, start); });
  });
}
