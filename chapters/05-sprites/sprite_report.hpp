#pragma once
// Chapter 5's report, its words apart from main.cpp's sections: the columns of the integrator and
// emission tables, and the sentences on the scene run (counts, work, frames).
#include <string>
#include <vector>

#include <kit/app/report.hpp>
#include <kit/sprites/sprite_run.hpp>

namespace kit {

/// Section 1's table: each integrator's order, fitted order and error at 1/fps [m] and [px].
inline std::vector<Column> integrator_columns() {
  return {{"integrator", "integrator"},
          {"order", "order"},
          {"fitted order", "fitted_order", "{:.3f}"},
          {"error at 1/fps [m]", "error_at_fps", "{:.2e}"},
          {"on screen [px]", "pixels_at_fps", "{:.2e}"}};
}

/// Section 2's table: each attribute as the scene gives it and as ex 5.1 drew it.
inline std::vector<Column> emission_columns() {
  return {{"attribute", "attribute"},
          {"scene mean", "mean", "{:.4g}"},
          {"± variance", "variance", "{:.4g}"},
          {"drawn mean", "drawn_mean", "{:.4g}"},
          {"drawn ± sqrt(3 var)", "drawn_half_width", "{:.4g}"}};
}

/// Section 3's sentences: the run's counts of particles, then its work in particle-steps by term.
inline void say_sprite_counts(Report& report, const SpriteRecording& rec, const std::string& scene,
                              const SpriteRunOptions& run) {
  const SpriteTotals& t = rec.totals;
  report.say("counts",
             "3. {frames} frames of '{scene}' with {integrator}: emitted {emitted}, "
             "dead {dead}, alive {alive} (the particles stored after the last frame; emitted - dead = "
             "{balance}); at most {peak} alive, {dropped} not emitted "
             "(--max-particles {max}).\n",
             {{"frames", long(rec.frames.size())},
              {"scene", scene},
              {"integrator", std::string(display_name(run.integrator))},
              {"emitted", t.emitted},
              {"dead", t.dead},
              {"alive", rec.frames.empty() ? 0L : rec.frames.back().alive},  // counted, not derived
              {"balance", t.alive()},
              {"peak", rec.peak_alive},
              {"dropped", t.dropped},
              {"max", run.max_particles}});
  const UpdateWork& w = rec.work;
  report.say("work",
             "Work in particle-steps: motion {steps}, gravity {gravity}, drag {drag}, colour "
             "{colour}, alpha {alpha}, size {size}, opacity tests {alpha_checks}, region tests "
             "{region_checks}: a term the scene does not list costs nothing.\n",
             {{"steps", w.particle_steps},
              {"gravity", w.gravity},
              {"drag", w.drag},
              {"colour", w.colour},
              {"alpha", w.alpha},
              {"size", w.size},
              {"alpha_checks", w.alpha_checks},
              {"region_checks", w.region_checks}});
}

/// Section 4's sentence: the frames rendered, where, and what the renderer did.
inline void say_sprite_frames(Report& report, const SpriteRecording& rec, const SpriteRunOptions& run) {
  report.say("frames",
             "4. {count} frames ({width}x{height}) in {dir}; {drawn} sprites drawn, "
             "{culled} culled, {pixels} pixels blended.\n",
             {{"count", long(rec.rendered.files.size())},
              {"width", long(run.width)},
              {"height", long(run.height)},
              {"dir", run.frame_dir.string()},
              {"drawn", rec.render.sprites_drawn},
              {"culled", rec.render.sprites_culled},
              {"pixels", rec.render.pixels_blended}});
}

}  // namespace kit
