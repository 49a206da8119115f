#pragma once
// What a rigid body run leaves on disk (chapter 8), as the cloth's (cloth_output.hpp): a rendered
// PNG per frame, an OBJ mesh per frame (flat faces with their normals; Blender and MeshLab open
// them), and the animation made of the frames.
#include <filesystem>
#include <string>
#include <vector>

#include <kit/rigid/rigid_body.hpp>
#include <kit/sprites/sprite_scene.hpp>

namespace kit {

/// Writes the body `shape` at `state` as an OBJ file, atomically (a temporary sibling renamed): a
/// comment header, `o <shape name>`, then per part a group `g part_<k>` and its six faces
/// (rigid_faces, rigid_mesh.hpp): each face's 4 corners in the world [m] as `v` lines with the
/// face's outward normal as their `vn` (24 vertices a box, so every face is flat), and its two
/// triangles (0, 1, 2) and (0, 2, 3) as `f a//a b//b c//c`, counter-clockwise seen from outside.
/// Numbers are written in the shortest form that reads back exactly. kit::read_obj reads it.
/// Throws std::runtime_error when it cannot write.
void write_rigid_obj(const std::filesystem::path& path, const RigidShape& shape, const RigidState& state);

struct RigidOutputOptions {
  std::filesystem::path dir;  ///< <stem>_frames/, <stem>_meshes/ and the animation go here; empty: nothing
  int width = 640, height = 480;  ///< [px]
  double fps = 30;                ///< frames per second of the animation [1/s]
  std::string stem;               ///< names the files (a run's body, "t-handle"); empty: the shape's name
};

struct RigidOutput {
  std::vector<std::filesystem::path> frames;  ///< <stem>_frames/frame_NNNN.png
  std::vector<std::filesystem::path> meshes;  ///< <stem>_meshes/<stem>_NNNN.obj
  std::vector<std::filesystem::path> movies;  ///< <stem>.mp4, <stem>.gif when ffmpeg ran
  std::filesystem::path player, sheet;        ///< <stem>_play.gp, <stem>_sheet.png
  std::string note;                           ///< the videos written, or why not
};

/// Renders every state of `frames` (render_rigid through `camera`) into options.dir/<stem>_frames/
/// and writes its mesh into options.dir/<stem>_meshes/, then the contact sheet, the videos (when
/// ffmpeg is installed) and the player (finish_animation, frame_writer.hpp). Stale frames and
/// <stem>_*.obj meshes of an earlier, longer run in those folders are removed first. With an empty
/// options.dir nothing is written. Throws std::invalid_argument for a size or fps that is not
/// positive, as Pinhole for a bad camera, std::runtime_error when a file cannot be written.
RigidOutput write_rigid_output(const RigidShape& shape, const std::vector<RigidState>& frames,
                               const Camera& camera, const RigidOutputOptions& options);

}  // namespace kit
