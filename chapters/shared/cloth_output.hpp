#pragma once
// What a cloth run leaves on disk (chapter 6): a rendered PNG per frame, an OBJ mesh per frame
// (with normals; Blender and MeshLab open them), and the animation made of the frames.
#include <filesystem>
#include <string>
#include <vector>

#include <kit/app/chapter_app.hpp>
#include <kit/cloth/cloth_run.hpp>
#include <kit/render/animation.hpp>

#include "cloth_flags.hpp"

namespace kit {

struct ClothOutputOptions {
  std::filesystem::path dir;      ///< frames/, meshes/ and the animation go here; empty: nothing
  int width = 640, height = 480;  ///< [px]
  double fps = 30;                ///< frames per second of the animation: frames / t_end
};

/// Where and how large, from the flags; no folder under --no-plot.
ClothOutputOptions cloth_output_options(const ClothFlags& flags, const CommonOptions& common,
                                        const ClothRunOptions& run);

struct ClothOutput {
  std::vector<std::filesystem::path> frames, meshes;  ///< frames/frame_NNNN.png, meshes/cloth_NNNN.obj
  std::vector<std::filesystem::path> movies;          ///< cloth.mp4, cloth.gif when ffmpeg ran
  std::filesystem::path player, sheet;                ///< cloth_play.gp, cloth_sheet.png
  std::string note;                                   ///< the videos written, or why not
};

/// Renders and writes every recorded frame of `rec`, its mesh, then the sheet, the videos and
/// the player. Stale frames and meshes of an earlier run in the same folders are removed first.
ClothOutput write_cloth_output(const ClothScene& scene, const ClothRecording& rec,
                               const ClothOutputOptions& options);

}  // namespace kit
