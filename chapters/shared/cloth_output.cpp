// What a cloth run leaves on disk (cloth_output.hpp).
#include "cloth_output.hpp"

#include <fmt/format.h>

#include <kit/cloth/cloth_renderer.hpp>
#include <kit/cloth/obj_mesh.hpp>
#include <kit/render/frame_writer.hpp>

namespace kit {
namespace fs = std::filesystem;

ClothOutputOptions cloth_output_options(const ClothFlags& flags, const CommonOptions& common,
                                        const ClothRunOptions& run) {
  ClothOutputOptions options;
  if (!common.no_plot) options.dir = fs::path(common.out_dir);
  options.width = int(flags.width), options.height = int(flags.height);
  options.fps = run.frames > 0 ? run.frames / run.t_end : 30.0;
  return options;
}

ClothOutput write_cloth_output(const ClothScene& scene, const ClothRecording& rec,
                               const ClothOutputOptions& options) {
  ClothOutput out;
  const fs::path meshes = options.dir / "meshes";
  fs::create_directories(meshes);
  for (const auto& entry : fs::directory_iterator(meshes))  // an earlier, longer run's meshes
    if (entry.path().extension() == ".obj" && entry.path().filename().string().rfind("cloth_", 0) == 0)
      fs::remove(entry.path());
  FrameWriter writer(options.dir / "frames", options.width, options.height, long(rec.frames.size()), 12);
  for (std::size_t k = 0; k < rec.frames.size(); ++k) {
    out.frames.push_back(
        writer.write(render_cloth(scene.grid, rec.frames[k], scene, options.width, options.height)));
    out.meshes.push_back(meshes / fmt::format("cloth_{:04d}.obj", k));
    write_cloth_obj(out.meshes.back(), scene.grid, rec.frames[k]);
  }
  const auto made = finish_animation(writer.frames(), options.fps, animation_targets(options.dir, "cloth"));
  if (!made) {
    out.note = "no frame was recorded (the cloth exploded first): no animation.";
    return out;
  }
  out.player = made->player, out.sheet = made->sheet, out.movies = made->movie.files;
  out.note =
      made->movie.files.empty() ? made->movie.note : "animation: " + made->movie.files.front().string();
  return out;
}

}  // namespace kit
