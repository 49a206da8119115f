#pragma once
// A run's rendered frames on disk and what they become (chapters 5 and 6): numbered PNGs written
// one by one, a few kept for a contact sheet, then an MP4 and a GIF (ffmpeg, when installed), a
// gnuplot player and the contact sheet.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <kit/render/animation.hpp>
#include <kit/render/image.hpp>

namespace kit {

/// The frames' names inside their folder, printf style: frame_0000.png, frame_0001.png, …
inline constexpr const char* frame_file_pattern = "frame_%04d.png";

/// Removes every frame_*.png in `dir` (nothing when it does not exist): an earlier, longer run's
/// frames would join this run's animation, since ffmpeg reads frames until one is missing.
void remove_stale_frames(const std::filesystem::path& dir);

/// The frames a run wrote: numbered from 0 without gaps, all width × height, in one folder.
struct FrameSequence {
  std::vector<std::filesystem::path> files;  ///< in order
  std::vector<Image> sheet;                  ///< copies of evenly spaced frames, for the sheet
  int width = 0, height = 0;                 ///< [px]
};

/// Writes a run's frames as dir/frame_0000.png, frame_0001.png, … , each atomically (write_png),
/// and keeps copies of some for a contact sheet: every max(1, planned_frames / sheet_frames)-th
/// frame from frame 0, at most sheet_frames of them.
class FrameWriter {
 public:
  /// Creates `dir` and removes its stale frames. Throws std::invalid_argument unless width and
  /// height are ≥ 1 and sheet_frames ≥ 0.
  FrameWriter(std::filesystem::path dir, int width, int height, long planned_frames = 0,
              int sheet_frames = 0);
  /// Writes `image` as the next frame and returns its path. Throws std::invalid_argument when
  /// the image is not width × height, std::runtime_error when the file cannot be written.
  std::filesystem::path write(const Image& image);

  const std::filesystem::path& dir() const { return dir_; }
  const FrameSequence& frames() const { return frames_; }
  /// Hands the sequence over (the writer is then empty).
  FrameSequence release() { return std::move(frames_); }

 private:
  std::filesystem::path dir_;
  FrameSequence frames_;
  long sheet_every_ = 1;
  int sheet_frames_ = 0;
};

/// Where finish_animation writes: the videos, the player and the contact sheet (empty: none).
struct AnimationTargets {
  std::filesystem::path mp4, gif, player, sheet;
};
/// out_dir/<stem>.mp4, <stem>.gif, <stem>_play.gp and <stem>_sheet.png.
AnimationTargets animation_targets(const std::filesystem::path& out_dir, const std::string& stem);

/// What finish_animation made.
struct AnimationOutputs {
  std::filesystem::path sheet, player;  ///< sheet empty when none was written
  AnimationResult movie;                ///< the videos, or why not
};

/// Turns written frames into the targets: the contact sheet of frames.sheet (4 a row, when
/// there are kept frames and a sheet target), the videos at `fps` [1/s] (encode_animation) and
/// the player (write_player, the frames' folder relative to the player's). Nothing, and
/// nullopt, when no frame was written. Throws std::invalid_argument unless fps > 0.
std::optional<AnimationOutputs> finish_animation(const FrameSequence& frames, double fps,
                                                 const AnimationTargets& targets);

}  // namespace kit
