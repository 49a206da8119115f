#pragma once
// Chapter 6's command-line flags: which scene, which integrator, how fine a step, how long, how
// many nodes, how large the frames. The scene gives the defaults; a flag overrides them.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <kit/app/chapter_app.hpp>
#include <kit/cloth/cloth_run.hpp>
#include <kit/cloth/cloth_scene.hpp>

namespace kit {

struct ClothFlags {
  std::string scene = "flag";      ///< a name under the chapter's scenes/ or a .toml path
  std::string integrator;          ///< explicit-euler, symplectic-euler, midpoint, rk4; empty: the scene's
  double dt = 0;                   ///< [s]; 0: the scene's
  double t_end = 0;                ///< [s]; 0: the scene's
  long resolution = 0;             ///< nodes across (rows follow, cells near square); 0: the scene's
  long frames = 0;                 ///< frames written; 0: the scene's
  long width = 640, height = 480;  ///< [px]
};

/// Adds --scene --integrator --dt --t-end --resolution --frames --width --height, each range
/// checked when the flags are parsed. `more_integrators`: names --integrator also accepts
/// (chapter 7's implicit methods), which apply_cloth_flags leaves to the caller.
void add_cloth_flags(ChapterApp& app, ClothFlags& flags,
                     const std::vector<std::string>& more_integrators = {});

/// The scene --scene names: scenes_dir/NAME.toml for a bare name, else the path as given.
/// UsageError for an unknown name (listing the shipped ones) or a bad file (file:line: key).
ClothScene load_cloth_scene_flag(const ClothFlags& flags, const std::filesystem::path& scenes_dir);

/// `scene` with the flags' overrides: --integrator, --dt, --t-end, --resolution (at_resolution),
/// --frames. UsageError naming the flag for an unknown integrator or a resolution the pins do not
/// fit.
ClothScene apply_cloth_flags(ClothScene scene, const ClothFlags& flags);

/// The scene as the --json summary reports it: every field, units in the key names' comments of
/// cloth_scene.hpp, absent parts as null.
nlohmann::json cloth_scene_summary(const ClothScene& scene);

/// The run the scene (with the flags applied) asks for: its integrator, Δt, end and frames.
ClothRunOptions cloth_run_options(const ClothScene& scene);

/// "--resolution 32 (32×22 nodes), --dt 0.0002 s, --t-end 3 s, --frames 90": the flags that set a
/// run's cost, for its estimate and its refusal.
std::string describe_cloth_flags(const ClothScene& scene);

}  // namespace kit
