#pragma once
// Chapter 5's command-line flags: which scene, how long, how large, which integrator. The scene
// gives the defaults of --frames, --fps and --max-particles; a flag overrides them.
#include <filesystem>
#include <string>

#include <kit/app/chapter_app.hpp>
#include <kit/sprites/sprite_run.hpp>
#include <kit/sprites/sprite_scene.hpp>

namespace kit {

struct SpriteFlags {
  std::string scene = "fountain";  ///< a name under the chapter's scenes/ or a .toml path
  long frames = 0;                 ///< 0: the scene's
  double fps = 0;                  ///< [1/s]; 0: the scene's
  long seed = 1;
  std::string integrator = "exact";
  long width = 640, height = 360;  ///< [px]
  long max_particles = 0;          ///< 0: the scene's
};

/// Adds --scene --frames --fps --seed --integrator --width --height --max-particles.
void add_sprite_flags(ChapterApp& app, SpriteFlags& flags);

/// The scene --scene names: scenes_dir/NAME.toml for a bare name, else the path as given.
/// UsageError for an unknown name (listing the shipped ones) or a bad file (file:line: key).
SpriteScene load_scene_flag(const SpriteFlags& flags, const std::filesystem::path& scenes_dir);

/// Loads every distinct texture the scene names, so a missing or unreadable PNG is a usage error
/// (naming the scene file and emitter[i].texture) before anything runs. Returns their bytes, mip
/// levels included, for the run's estimate.
double check_textures(const SpriteScene& scene);

/// The run the flags ask for on `scene`, frames written under `frame_dir` (empty: none).
SpriteRunOptions run_options(const SpriteFlags& flags, const SpriteScene& scene,
                             const std::filesystem::path& frame_dir);

/// The summary's "scene" object: the scene, its file, and what the run uses of it.
nlohmann::json run_summary(const SpriteScene& scene, const SpriteRunOptions& run, const SpriteFlags& flags);

}  // namespace kit
