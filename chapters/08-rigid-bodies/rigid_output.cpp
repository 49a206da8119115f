// What a rigid body run leaves on disk (rigid_output.hpp).
#include "rigid_output.hpp"

#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include <kit/base/atomic_file.hpp>
#include <kit/render/frame_writer.hpp>
#include <kit/rigid/rigid_mesh.hpp>
#include <kit/rigid/rigid_renderer.hpp>

namespace kit {
namespace fs = std::filesystem;
namespace {

// Removes <stem>_*.obj in `dir`: an earlier, longer run's meshes would pass for this run's.
void remove_stale_meshes(const fs::path& dir, const std::string& stem) {
  std::error_code missing;
  for (const auto& entry : fs::directory_iterator(dir, missing))
    if (entry.path().extension() == ".obj" && entry.path().filename().string().starts_with(stem + "_"))
      fs::remove(entry.path());
}

}  // namespace

void write_rigid_obj(const fs::path& path, const RigidShape& shape, const RigidState& state) {
  const std::vector<RigidFace> faces = rigid_faces(shape, state);
  std::string text =
      fmt::format("# Rigid body '{}', {} box part{}, {} triangles; positions in metres, world frame (y up).\n"
                  "# Written by the physics-for-animation kit; opens in Blender and MeshLab.\n"
                  "o {}\n",
                  shape.name, shape.parts.size(), shape.parts.size() == 1 ? "" : "s", 2 * faces.size(),
                  shape.name.empty() ? "body" : shape.name);
  text.reserve(text.size() + faces.size() * 4 * 140);
  // `{}` prints a double in the shortest form that reads back to the same double.
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const RigidFace& face = faces[f];
    if (f == 0 || face.part != faces[f - 1].part) text += fmt::format("g part_{}\n", face.part);
    for (const Vec3& corner : face.corners)
      text += fmt::format("v {} {} {}\n", corner.x(), corner.y(), corner.z());
    for (int k = 0; k < 4; ++k)
      text += fmt::format("vn {} {} {}\n", face.normal.x(), face.normal.y(), face.normal.z());
    const std::size_t first = 4 * f + 1;  // OBJ counts from 1
    text += fmt::format("f {0}//{0} {1}//{1} {2}//{2}\nf {0}//{0} {2}//{2} {3}//{3}\n", first, first + 1,
                        first + 2, first + 3);
  }
  write_file_atomic(path, text);
}

RigidOutput write_rigid_output(const RigidShape& shape, const std::vector<RigidState>& frames,
                               const Camera& camera, const RigidOutputOptions& options) {
  RigidOutput out;
  if (options.dir.empty()) return out;
  if (!(options.fps > 0)) throw std::invalid_argument(fmt::format("fps must be > 0, not {}", options.fps));
  const std::string stem = !options.stem.empty() ? options.stem : !shape.name.empty() ? shape.name : "body";
  const fs::path meshes = options.dir / (stem + "_meshes");
  fs::create_directories(meshes);
  remove_stale_meshes(meshes, stem);
  FrameWriter writer(options.dir / (stem + "_frames"), options.width, options.height, long(frames.size()),
                     12);
  if (frames.empty()) {  // the stale files are gone, and there is nothing to animate
    out.note = "no state to draw: no frames, no animation.";
    return out;
  }
  for (std::size_t k = 0; k < frames.size(); ++k) {
    out.frames.push_back(writer.write(render_rigid(shape, frames[k], camera, options.width, options.height)));
    out.meshes.push_back(meshes / fmt::format("{}_{:04d}.obj", stem, k));
    write_rigid_obj(out.meshes.back(), shape, frames[k]);
  }
  // Frames were written, so finish_animation has made something.
  const AnimationOutputs made =
      *finish_animation(writer.frames(), options.fps, animation_targets(options.dir, stem));
  out.player = made.player, out.sheet = made.sheet, out.movies = made.movie.files;
  out.note = made.movie.files.empty() ? made.movie.note : "animation: " + made.movie.files.front().string();
  return out;
}

}  // namespace kit
