#include <kit/sprite_run.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include <kit/progress.hpp>

namespace kit {
namespace {
// Per-particle-step and per-pixel costs [s]: conservative constants for a 2020s core (the
// update moves 64 B a particle-step; a frame's pixels are cleared, blended and PNG-encoded).
constexpr double seconds_per_particle_step = 5e-9;
constexpr double seconds_per_sprite = 2e-7;
constexpr double seconds_per_pixel = 4e-8;

bool finite_positions(const Particles& ps) {
  float sum = 0;  // one non-finite coordinate makes the sum non-finite
  for (std::size_t i = 0; i < ps.size(); ++i) sum += ps.x[i] + ps.y[i] + ps.z[i];
  return std::isfinite(sum);
}
}  // namespace

double expected_alive(const SpriteScene& scene, const SpriteRunOptions& options) {
  double alive = 0;
  for (const Emitter& e : scene.emitters)
    if (!e.burst_only) alive += e.rate.mean * e.lifetime.mean * options.fps;
  return std::min(alive, double(options.max_particles));
}

RunEstimate estimate_sprite_run(const SpriteScene& scene, const SpriteRunOptions& options) {
  const double alive = expected_alive(scene, options), pixels = double(options.width) * options.height;
  const bool render = !options.frame_dir.empty();
  RunEstimate estimate;
  estimate.steps = double(options.frames + options.warmup_frames);
  estimate.seconds_per_step =
      alive * seconds_per_particle_step + (render ? alive * seconds_per_sprite + pixels * seconds_per_pixel : 0.0) *
      double(options.frames) / double(options.frames + options.warmup_frames);
  // The arrays, the renderer's sprite lists, and the frame plus the contact sheet's frames.
  estimate.bytes = double(options.max_particles) * double(Particles::bytes_per_particle + 40) +
                   (render ? pixels * 12.0 * (1 + options.sheet_frames) : 0.0);
  return estimate;
}

SpriteRecording run_sprite_scene(const SpriteScene& scene, const SpriteRunOptions& options, SpriteKernels kernels) {
  SpriteRecording rec;
  rec.warmup_frames = options.warmup_frames;
  ProgressTask::set_total(double(options.warmup_frames + options.frames));  // the section's bar counts frames
  SpriteSystem system(scene, options.max_particles, options.fps, options.seed, options.integrator, kernels);
  const bool render = !options.frame_dir.empty();
  std::optional<SpriteRenderer> renderer;
  if (render) {
    renderer.emplace(scene, options.width, options.height);
    renderer->composite_over_with(options.over);
    std::filesystem::create_directories(options.frame_dir);
  }
  Image image(options.width, options.height, scene.background);
  // Paths: every stride-th particle of the first half of the run's expected emissions.
  const double per_frame = expected_alive(scene, options) / std::max(1.0, options.fps * scene.emitters[0].lifetime.mean);
  const auto stride = std::uint32_t(std::max(1.0, std::floor(per_frame * double(options.frames) / 2 / options.paths)));
  std::map<std::uint32_t, ParticlePath> paths;
  const long sheet_every = std::max(1L, options.frames / std::max(1, options.sheet_frames));
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
    for (std::size_t i = 0; i < ps.size(); ++i) {
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
      rec.frame_files.push_back(options.frame_dir / fmt::format("frame_{:04d}.png", f));
      write_png(image, rec.frame_files.back());
      if (f % sheet_every == 0 && long(rec.sheet.size()) < options.sheet_frames) rec.sheet.push_back(image);
    }
    progress_add(1);
  }
  rec.totals = system.totals();
  rec.work = system.work();
  for (auto& [id, path] : paths) rec.paths.push_back(std::move(path));
  return rec;
}

}  // namespace kit
