#include <kit/sprites/sprite_run.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include <kit/app/progress.hpp>

namespace kit {
namespace {

bool finite_positions(const Particles& ps) {
  float sum = 0;  // one non-finite coordinate makes the sum non-finite
  for (std::size_t i = 0; i < ps.size(); ++i) sum += ps.x[i] + ps.y[i] + ps.z[i];
  return std::isfinite(sum);
}
}  // namespace

std::vector<double> emissions_per_frame(const SpriteScene& scene) {
  std::vector<double> rate(scene.emitters.size(), 0.0);
  for (std::size_t i = 0; i < rate.size(); ++i)
    if (!scene.emitters[i].burst_only) rate[i] = std::max(scene.emitters[i].rate.mean, 0.0);
  // Every particle dies once, so a parent emitting r a frame bursts r times a frame. Chains are
  // acyclic (the loader refuses loops), so as many passes as emitters settle them.
  for (std::size_t pass = 0; pass < rate.size(); ++pass)
    for (std::size_t i = 0; i < rate.size(); ++i) {
      if (!scene.emitters[i].burst_only) continue;
      double bursts = 0;
      for (std::size_t p = 0; p < rate.size(); ++p)
        if (scene.emitters[p].on_death == int(i)) bursts += rate[p];
      rate[i] = bursts * std::max(scene.emitters[i].rate.mean, 0.0);
    }
  return rate;
}

double expected_alive(const SpriteScene& scene, const SpriteRunOptions& options) {
  const std::vector<double> rate = emissions_per_frame(scene);
  double alive = 0;
  for (std::size_t i = 0; i < rate.size(); ++i)
    alive += rate[i] * scene.emitters[i].lifetime.mean * options.fps;
  return std::min(alive, double(options.max_particles));
}

SpriteRecording run_sprite_scene(const SpriteScene& scene, const SpriteRunOptions& options,
                                 SpriteKernels kernels) {
  SpriteRecording rec;
  rec.warmup_frames = options.warmup_frames;
  ProgressTask::set_total(double(options.warmup_frames + options.frames));  // the section's bar counts frames
  SpriteSystem system(scene, options.max_particles, options.fps, options.seed, options.integrator, kernels);
  const bool render = !options.frame_dir.empty();
  std::optional<SpriteRenderer> renderer;
  std::optional<FrameWriter> writer;
  if (render) {
    renderer.emplace(scene, options.width, options.height);
    renderer->composite_over_with(options.over);
    writer.emplace(options.frame_dir, options.width, options.height, options.frames, options.sheet_frames);
  }
  Image image(options.width, options.height, scene.background);
  // Paths: every stride-th particle of the first half of the run's expected emissions.
  const double per_frame =
      expected_alive(scene, options) / std::max(1.0, options.fps * scene.emitters[0].lifetime.mean);
  const auto stride =
      std::uint32_t(std::max(1.0, std::floor(per_frame * double(options.frames) / 2 / options.paths)));
  std::map<std::uint32_t, ParticlePath> paths;
  for (long k = 0; k < options.warmup_frames + options.frames; ++k) {
    const long f = k - options.warmup_frames;  // the rendered frame's number; negative while warming up
    const FrameCounts counts = system.step();
    rec.frames.push_back(counts);
    rec.peak_alive = std::max(rec.peak_alive, counts.alive);
    const Particles& ps = system.particles();
    if (!finite_positions(ps)) {
      rec.diverged_at = k;
      break;
    }
    // Ids are 32-bit serial numbers: after 2^32 emissions they repeat, and paths stop growing.
    const bool ids_unique = system.totals().emitted <= long(std::numeric_limits<std::uint32_t>::max());
    for (std::size_t i = 0; ids_unique && i < ps.size(); ++i) {
      if (ps.id[i] % stride != 0 || ps.id[i] / stride >= std::uint32_t(options.paths)) continue;
      ParticlePath& path = paths[ps.id[i]];
      path.id = ps.id[i];
      path.x.push_back(ps.x[i]), path.y.push_back(ps.y[i]), path.z.push_back(ps.z[i]);
      path.age.push_back(ps.age[i]);
    }
    if (render && f >= 0) {
      const RenderStats s = renderer->render(ps, image);
      rec.render.sprites_drawn += s.sprites_drawn, rec.render.sprites_culled += s.sprites_culled;
      rec.render.pixels_blended += s.pixels_blended;
      writer->write(image);  // frame f, from 0
    }
    progress_add(1);
  }
  if (writer) rec.rendered = writer->release();
  rec.totals = system.totals();
  rec.work = system.work();
  for (auto& [id, path] : paths) rec.paths.push_back(std::move(path));
  return rec;
}

std::optional<AnimationOutputs> write_animation(const SpriteRecording& rec, const SpriteRunOptions& options,
                                                const std::filesystem::path& out) {
  return finish_animation(
      rec.rendered, options.fps,
      {out / "animation.mp4", out / "animation.gif", out / "play.gp", out / "contact_sheet.png"});
}

}  // namespace kit
