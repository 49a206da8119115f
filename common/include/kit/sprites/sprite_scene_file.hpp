#pragma once
// A sprite scene read from a TOML file (chapter 5; Reeves 1983). The file lists only what the
// scene uses: every key it leaves out keeps its default from sprite_scene.hpp, and an absent force
// stays std::nullopt, so the simulation computes nothing for it. Every mistake is a UsageError
// (exit 2) that names the file, the line, the full dotted key, the bad value and what is allowed:
//   scenes/fountain.toml:12: emitter[0].speed.variance = -1: must be a finite number >= 0
//
// Schema (units in brackets; "spread" = a number, or { mean = .., variance = .. } with variance
// the half-width of a uniform draw mean ± variance, >= 0; a number means variance 0):
//
//   name           string, required, not empty
//   frames         integer in [1, 20000]                  default 120
//   fps            number in [1, 1000]                    default 30
//   warmup         number in [0, 600] [s], simulated before frame 0 (not rendered)   default 0
//   max_particles  integer in [1, 1e12]                   default 100000
//   background     [r, g, b], each in [0, 1]              linear RGB
//   [camera]       position, target: [x, y, z] [m], target != position; fov_deg in [1, 170]
//                  (vertical field of view [deg])
//   [forces]       gravity [x, y, z] [m/s²]; drag k in (0, 1000] [1/s], a = −k (v − wind);
//                  wind [x, y, z] [m/s], which acts through drag and so needs drag
//   [death]        alpha_below in [0, 1); region = { min = [x, y, z], max = [x, y, z] } [m],
//                  min < max in every component; leaving the box kills
//   [[emitter]]    1 to 255 of them, each with:
//     name             string, required, unique (on_death refers to it)
//     shape            "point" | "disc" | "sphere" | "cone"   default "point"
//     position         [x, y, z] [m]
//     axis             [x, y, z], not zero, normalised on load  default [0, 1, 0]
//     radius           [m] in [0, 1e6]; > 0 for disc and sphere
//     angle_deg        half-angle [deg] in [0, 180] (disc and cone)
//     rate             spread, particles per frame (per burst when burst_only); mean in [0, 1e7],
//                      variance may exceed the mean: a negative draw emits nothing
//     speed            spread [m/s], every draw in [0, 1e5]
//     lifetime         spread [s], every draw in (0, 1e6]
//     size             spread [m], every draw in [0, 1e6]
//     alpha            spread, every draw in [0, 1]
//     colour           [r, g, b] in [0, 1];  colour_variance: [r, g, b] in [0, 1]
//     colour_rate      [r, g, b] [1/s];  alpha_rate [1/s];  size_rate [m/s]  (each in [-1000, 1000])
//     blend            "over" | "additive"                    default "over"
//     texture          "soft" | "spark" | "flake" | "smoke" or a path ending in .png, relative
//                      to the scene file's folder (resolved on load, not checked for existence)
//     burst_only       boolean: emits only when another emitter's particle dies; such an emitter
//                      must be some emitter's on_death
//     on_death         name of the emitter that bursts where this one's particles die; not itself,
//                      and no loop of bursts
//     inherit_velocity fraction in [0, 1] of the dead particle's velocity a burst inherits
//     first_frame      integer >= 0;  last_frame: integer >= first_frame
//
// chapters/05-sprites/scenes/README.md has the same schema as a table.
#include <filesystem>
#include <string_view>

#include <kit/sprites/sprite_scene.hpp>

namespace kit {

/// Reads and checks a scene file. Throws UsageError, also when the file cannot be read.
SpriteScene load_sprite_scene(const std::filesystem::path& file);

/// Parses and checks a scene held in `text`; `file_name` names it in messages, becomes
/// SpriteScene::file, and is the folder relative texture paths are resolved against.
SpriteScene parse_sprite_scene(std::string_view text, std::string_view file_name);

}  // namespace kit
