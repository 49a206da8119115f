#include <kit/render/frame_writer.hpp>

#include <algorithm>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include <kit/render/contact_sheet.hpp>

namespace kit {

void remove_stale_frames(const std::filesystem::path& dir) {
  std::error_code missing;
  for (const auto& entry : std::filesystem::directory_iterator(dir, missing))
    if (entry.path().filename().string().starts_with("frame_") && entry.path().extension() == ".png")
      std::filesystem::remove(entry.path());
}

FrameWriter::FrameWriter(std::filesystem::path dir, int width, int height, long planned_frames,
                         int sheet_frames)
    : dir_(std::move(dir)), sheet_frames_(sheet_frames) {
  if (width < 1 || height < 1)
    throw std::invalid_argument(fmt::format("frames need at least 1 x 1 pixels, not {} x {}", width, height));
  if (sheet_frames < 0)
    throw std::invalid_argument(fmt::format("sheet_frames must be >= 0, not {}", sheet_frames));
  frames_.width = width, frames_.height = height;
  sheet_every_ = std::max(1L, planned_frames / std::max(1, sheet_frames));
  std::filesystem::create_directories(dir_);
  remove_stale_frames(dir_);
}

std::filesystem::path FrameWriter::write(const Image& image) {
  if (image.width != frames_.width || image.height != frames_.height)
    throw std::invalid_argument(fmt::format("a frame of {} x {} pixels among frames of {} x {}", image.width,
                                            image.height, frames_.width, frames_.height));
  const long number = long(frames_.files.size());
  std::filesystem::path file = dir_ / fmt::format("frame_{:04d}.png", number);
  write_png(image, file);
  frames_.files.push_back(file);
  if (number % sheet_every_ == 0 && long(frames_.sheet.size()) < sheet_frames_)
    frames_.sheet.push_back(image);
  return file;
}

AnimationTargets animation_targets(const std::filesystem::path& out_dir, const std::string& stem) {
  return {out_dir / (stem + ".mp4"), out_dir / (stem + ".gif"), out_dir / (stem + "_play.gp"),
          out_dir / (stem + "_sheet.png")};
}

std::optional<AnimationOutputs> finish_animation(const FrameSequence& frames, double fps,
                                                 const AnimationTargets& targets) {
  if (!(fps > 0)) throw std::invalid_argument(fmt::format("fps must be > 0, not {}", fps));
  if (frames.files.empty()) return std::nullopt;
  AnimationOutputs made;
  if (!frames.sheet.empty() && !targets.sheet.empty()) {
    made.sheet = targets.sheet;
    write_png(contact_sheet(frames.sheet, 4, 8), made.sheet);
  }
  const std::filesystem::path frame_dir = frames.files.front().parent_path();
  made.movie = encode_animation(frame_dir / frame_file_pattern, fps, targets.mp4, targets.gif);
  made.player = targets.player;
  const auto pattern =
      std::filesystem::relative(frame_dir, targets.player.parent_path()) / frame_file_pattern;
  write_player(made.player, pattern.string(), long(frames.files.size()), fps, frames.width, frames.height);
  return made;
}

}  // namespace kit
