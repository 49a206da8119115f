// Chapter 5: sprites (lecture, "Applications / Sprites"; Reeves 1983). A sprite is a particle
// that falls under gravity, lives for a limited time and is drawn as an animated, transparent
// texture; its trajectory can be shown. The chapter prices the integrators against the closed
// form of gravity plus drag, runs a scene (ex 5.1 emits, ex 5.2 ages and kills), renders its
// frames (ex 5.3 composites "over"), and draws the counts and the paths.
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include <kit/app/chapter_app.hpp>
#include <kit/base/measure.hpp>
#include <kit/render/animation.hpp>
#include <kit/render/page_output.hpp>
#include <kit/sprites/sprite_estimate.hpp>

#include "emission_check.hpp"
#include "sprite_figures.hpp"
#include "sprite_flags.hpp"
#include "sprite_kernels.hpp"
#include "sprite_report.hpp"

namespace {
namespace fs = std::filesystem;

// 1. "Particule tombant sous gravité": each integrator on the scene's mean particle against the
//    closed form, at the frame rate and over a sweep of Δt; the error in metres and on screen.
void falls_under_gravity(kit::ChapterApp& app, const kit::SpriteScene& scene,
                         const kit::SpriteRunOptions& run) {
  const kit::DragProblem mean = kit::mean_particle(scene);
  const kit::Pinhole camera(scene.camera, run.width, run.height);
  app.report().say("trade",
                   "1. The mean particle of '{scene}' over its life of {t:.3g} s (k = {k} 1/s), "
                   "against the closed form x(t) of gravity plus drag:\n",
                   {{"scene", scene.name}, {"t", mean.t_end}, {"k", mean.drag}});
  auto table = app.report().table("integrators", kit::integrator_columns());
  kit::TradeCurves curves;
  for (kit::Integrator i : kit::all_integrators) {
    const auto& runs = curves[i] = kit::trade_runs(mean, i, kit::trade_steps());
    std::vector<double> dts, errors;  // the order, fitted where asymptotic (kΔt < 0.5) and above round-off
    for (const auto& r : runs)
      if (r.dt * mean.drag < 0.5 && r.error > kit::trade_roundoff(r))
        dts.push_back(r.dt), errors.push_back(r.error);
    const kit::TradeRun at_fps = kit::trade_runs(mean, i, {1.0 / run.fps}).front();
    table.row(kit::flag_name(i),
              {std::string(kit::display_name(i)), long(kit::order(i)),
               dts.size() > 2 ? kit::ReportValue(kit::fit_loglog(dts, errors).slope) : kit::ReportValue{},
               at_fps.error, kit::pixels_between(camera, at_fps.position, at_fps.exact)});
  }
  table.print();
  app.report().print("All four cost the same per particle-step (one affine map per axis); the exact step "
                     "is free accuracy.\n\n");
  app.figure(kit::trade_figure(curves, camera, run.fps, scene.name));
}

// 2. Reeves's emission as ex 5.1 draws it: each attribute's mean and half-width over 20000 draws.
void emits(kit::ChapterApp& app, const kit::SpriteScene& scene, std::uint64_t seed) {
  const auto draws = kit::measure_emission(scene.emitters[0], &kit::sample_particle, seed);
  app.report().print(fmt::format("2. Emitter '{}', 20000 particles drawn by your sample_particle:\n",
                                 scene.emitters[0].name));
  auto table = app.report().table("emission", kit::emission_columns());
  for (const auto& a : draws) table.row({a.name, a.mean, a.half_width, a.drawn_mean, a.drawn_half_width});
  table.print();
  app.report().print("\n");
}

// 3. "Durée de vie limitée": the scene runs; every particle dies at the end of its life, or
//    sooner by the scene's rules, and alive = emitted − dead after every frame.
kit::SpriteRecording lives_and_dies(kit::ChapterApp& app, const kit::SpriteScene& scene,
                                    const kit::SpriteRunOptions& run) {
  const kit::SpriteRecording rec = kit::run_sprite_scene(scene, run, kit::student_kernels(scene.emitters[0]));
  kit::say_sprite_counts(app.report(), rec, scene.name, run);
  if (rec.diverged_at >= 0)
    app.diverged("scene", fmt::format("a position became infinite at frame {} (Δt = 1/{} s); the frames "
                                      "so far are kept",
                                      rec.diverged_at, run.fps));
  app.figure(kit::counts_figure(rec, run.fps, scene.name));
  return rec;
}

// 4. "Plaque une texture transparente animée": the frames as a contact sheet and an animation.
void animated_texture(kit::ChapterApp& app, const kit::SpriteScene& scene, const kit::SpriteRecording& rec,
                      const kit::SpriteRunOptions& run) {
  const fs::path out = app.options().out_dir;
  kit::say_sprite_frames(app.report(), rec, run);
  const auto made = kit::write_animation(rec, run, out);
  if (!made) {
    app.report().print("No frame was rendered (the run diverged first): no contact sheet, no animation.\n");
    return;
  }
  app.summary()["figures"]["contact_sheet"] = {made->sheet.string()};
  std::string movie = "Animation:";
  for (const auto& file : made->movie.files) {
    app.summary()["figures"]["animation"].push_back(file.string());
    movie.append(" ").append(file.string());  // not " " + …: a false -Wrestrict alarm of GCC 12
  }
  app.report().say(
      "animation", "{files}\nPlay the frames: gnuplot -persist {player}\n",
      {{"files", made->movie.files.empty() ? made->movie.note : movie}, {"player", made->player.string()}});
  if (app.options().show) app.report().print(kit::show_player(made->player) + "\n");
  kit::write_page(app, kit::sprite_page(scene, rec, run), out / "sprites.html");
}

// 5. "On peut afficher la trajectoire": a sample of paths, coloured by age.
void trajectories(kit::ChapterApp& app, const kit::SpriteRecording& rec, const kit::SpriteScene& scene) {
  app.report().say("paths", "5. Paths of {count} particles, side view, coloured by age.\n",
                   {{"count", long(rec.paths.size())}});
  app.figure(kit::paths_figure(rec, scene.name));
}
}  // namespace

int main(int argc, char** argv) {
  kit::SpriteFlags flags;
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 5: sprites, a particle system");
  kit::add_sprite_flags(app, flags);
  app.add_divergence_flag();
  return app.run(argc, argv, [&] {
    const kit::SpriteScene scene = kit::load_scene_flag(flags, fs::path(KIT_CHAPTER_SOURCE_DIR) / "scenes");
    const bool render = !app.options().no_plot;
    const fs::path frames = render ? fs::path(app.options().out_dir) / "frames" : fs::path();
    auto run = kit::run_options(flags, scene, frames);
    run.page_particles = render && !app.options().no_viewer ? 1500 : 0;  // the 3D page's, a frame
    kit::announce_run(app.report(), "animation", "The animation", kit::estimate_sprite_run(scene, run),
                      fmt::format("--frames {}, --fps {}, --max-particles {}, --width {}, --height {}",
                                  run.frames, run.fps, run.max_particles, run.width, run.height),
                      {.max_bytes = kit::machine_memory()});
    app.summary()["scene"] = kit::run_summary(scene, run, flags);
    app.section("the integrators", [&] { falls_under_gravity(app, scene, run); });
    app.section("the emission", [&] { emits(app, scene, run.seed); });
    run.over = render ? kit::student_over(app.report()) : nullptr;
    app.section("the scene", [&] {
      const kit::SpriteRecording rec = lives_and_dies(app, scene, run);
      if (render) animated_texture(app, scene, rec, run);
      trajectories(app, rec, scene);
    });
  });
}
