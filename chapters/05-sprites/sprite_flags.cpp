#include "sprite_flags.hpp"

#include <climits>
#include <map>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>

#include <kit/app/scene_flag.hpp>
#include <kit/base/usage.hpp>
#include <kit/sprites/sprite_scene_file.hpp>
#include <kit/sprites/sprite_texture.hpp>

namespace kit {
namespace {
Integrator integrator_named(const std::string& name) {
  if (const auto integrator = integrator_names.parse(name)) return *integrator;
  throw UsageError(
      fmt::format("--integrator: '{}' is not one of {}", name, fmt::join(integrator_names.flags(), ", ")));
}

}  // namespace

void add_sprite_flags(ChapterApp& app, SpriteFlags& f) {
  app.cli()
      .add_option("--scene", f.scene,
                  "scene: a name under chapters/05-sprites/scenes/ or a path to a .toml file")
      ->type_name("NAME|FILE");
  app.add_count("--frames", f.frames, "frames to run (default: the scene's)", 1, 20000);
  app.add_real("--fps", f.fps, "frames per second, Δt = 1/fps [1/s] (default: the scene's)",
               between(1, 1000));
  app.add_count("--seed", f.seed, "random seed: the same seed gives the same frames and data", 0, LONG_MAX);
  app.add_choice("--integrator", f.integrator,
                 "euler, symplectic, midpoint or exact (the closed form of gravity plus drag)",
                 integrator_names.flags());
  app.add_count("--width", f.width, "frame width [px]", 16, 7680);
  app.add_count("--height", f.height, "frame height [px]", 16, 4320);
  app.add_count("--max-particles", f.max_particles, "particles alive at most (default: the scene's)", 1,
                max_particles_bound);
  app.add_viewer_flag();
}

SpriteScene load_scene_flag(const SpriteFlags& flags, const std::filesystem::path& scenes_dir) {
  return load_sprite_scene(scene_file(flags.scene, scenes_dir));
}

double check_textures(const SpriteScene& scene) {
  std::map<std::string, double> bytes;
  for (std::size_t i = 0; i < scene.emitters.size(); ++i) {
    const std::string& name = scene.emitters[i].texture;
    if (bytes.count(name)) continue;
    try {
      const Texture t = texture_for(name);
      bytes[name] = double(t.rgba.size() * sizeof(float)) * 4.0 / 3.0;  // mip levels add a third
    } catch (const UsageError& e) {
      throw UsageError(fmt::format("{}: emitter[{}].texture: {}", scene.file, i, e.what()));
    }
  }
  double total = 0;
  for (const auto& [name, b] : bytes) total += b;
  return total;
}

SpriteRunOptions run_options(const SpriteFlags& flags, const SpriteScene& scene,
                             const std::filesystem::path& frame_dir) {
  SpriteRunOptions o;
  o.frames = flags.frames > 0 ? flags.frames : scene.frames;
  o.fps = flags.fps > 0 ? flags.fps : scene.fps;
  o.warmup_frames = std::lround(scene.warmup * o.fps);
  o.seed = std::uint64_t(flags.seed);
  o.integrator = integrator_named(flags.integrator);
  o.max_particles = flags.max_particles > 0 ? flags.max_particles : scene.max_particles;
  o.width = int(flags.width), o.height = int(flags.height);
  o.frame_dir = frame_dir;
  o.texture_bytes = check_textures(scene);
  return o;
}

nlohmann::json run_summary(const SpriteScene& scene, const SpriteRunOptions& run, const SpriteFlags& flags) {
  return {{"name", scene.name},
          {"file", scene.file},
          {"frames", run.frames},
          {"fps", run.fps},
          {"max_particles", run.max_particles},
          {"integrator", flags.integrator},
          {"warmup_frames", run.warmup_frames}};
}

}  // namespace kit
