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

namespace {

// Linear [0, 1] to an sRGB byte, as a browser shows colours.
std::uint8_t srgb_byte(float linear) {
  const double c = std::clamp(double(linear), 0.0, 1.0);
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
  return std::uint8_t(std::lround(255 * s));
}

// Every k-th alive particle, k the smallest that keeps at most the frame's share.
void keep_for_page(const Particles& ps, const SpriteRunOptions& options, PagePoints& page) {
  const long share =
      std::max(1L, std::min(options.page_particles, page_particle_frames / std::max(1L, options.frames)));
  const std::size_t every =
      std::max<std::size_t>(1, (ps.size() + std::size_t(share) - 1) / std::size_t(share));
  std::vector<Vec3> positions;
  std::vector<std::array<std::uint8_t, 4>> colours;
  for (std::size_t i = 0; i < ps.size(); i += every) {
    positions.emplace_back(ps.x[i], ps.y[i], ps.z[i]);
    colours.push_back({srgb_byte(ps.r[i]), srgb_byte(ps.g[i]), srgb_byte(ps.b[i]),
                       std::uint8_t(std::lround(255 * std::clamp(double(ps.alpha[i]), 0.0, 1.0)))});
  }
  page.frames.push_back(std::move(positions));
  page.rgba.push_back(std::move(colours));
}

}  // namespace

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
    if (options.page_particles > 0 && f >= 0) keep_for_page(ps, options, rec.page);
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

WebPage sprite_page(const SpriteScene& scene, const SpriteRecording& rec, const SpriteRunOptions& options) {
  WebPage page;
  page.title = fmt::format("Chapter 5: '{}'", scene.name);
  page.subtitle =
      fmt::format("{} frames at {:g} per second after {} warm-up frames; every k-th particle shown",
                  options.frames, options.fps, options.warmup_frames);
  page.fps = options.fps;
  page.background = fmt::format("#{:02x}{:02x}{:02x}", srgb_byte(float(scene.background[0])),
                                srgb_byte(float(scene.background[1])), srgb_byte(float(scene.background[2])));
  PagePane pane;
  pane.label = fmt::format("{}, Δt = 1/{:g} s", display_name(options.integrator), options.fps);
  pane.facts = {{"emitters", fmt::format("{}", scene.emitters.size())},
                {"most alive", fmt::format("{}", options.max_particles)}};
  pane.points.push_back(rec.page);
  pane.points.back().name = "particles";
  pane.points.back().size = scene.emitters.empty() ? 0.1 : scene.emitters.front().size.mean;
  PageReadout alive{"alive", "", {}, 6}, emitted{"emitted this frame", "", {}, 6}, shown{"shown", "", {}, 6};
  for (std::size_t f = 0; f < rec.page.frames.size(); ++f) {
    const FrameCounts& counts = rec.frames[std::size_t(rec.warmup_frames) + f];
    // A frame is drawn after its update; the warm-up's frames came first.
    page.times.push_back(double(rec.warmup_frames + long(f) + 1) / options.fps);
    alive.values.push_back(double(counts.alive));
    emitted.values.push_back(double(counts.emitted));
    shown.values.push_back(double(rec.page.frames[f].size()));
  }
  pane.readouts = {alive, emitted, shown};
  if (rec.diverged_at >= 0)
    pane.ended = fmt::format("a position became infinite at frame {}", rec.diverged_at);
  page.panes.push_back(std::move(pane));
  return page;
}

std::optional<AnimationOutputs> write_animation(const SpriteRecording& rec, const SpriteRunOptions& options,
                                                const std::filesystem::path& out) {
  return finish_animation(
      rec.rendered, options.fps,
      {out / "animation.mp4", out / "animation.gif", out / "play.gp", out / "contact_sheet.png"});
}

}  // namespace kit
