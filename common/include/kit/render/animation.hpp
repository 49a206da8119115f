#pragma once
// Turns a run's PNG frames into an MP4 and a GIF with ffmpeg, when ffmpeg is installed: it is
// optional, so without it the frames stay and the note says how to get the videos (chapter 5).
#include <filesystem>
#include <string>
#include <vector>

namespace kit {

struct AnimationResult {
  std::vector<std::filesystem::path> files;  ///< the videos written, in order MP4, GIF
  std::string note;                          ///< empty when both were written; else why not
};

/// The ffmpeg executable on PATH (the first executable "ffmpeg" in PATH's folders), or an empty
/// path when there is none.
std::filesystem::path find_ffmpeg();

/// Encodes the frames matching `frame_pattern` (printf style, e.g. dir/frame_%04d.png, numbered
/// from 0 or 1 on; ffmpeg's image2 input) at `fps` frames per second into `mp4` (H.264, yuv420p,
/// padded to even width and height as yuv420p needs) and `gif` (one palette made for the whole
/// clip). ffmpeg runs directly (no shell), stdin from /dev/null, its messages to a log read back
/// into the note on failure. Each video is written into a scratch folder beside it (ScratchFolder,
/// atomic_file.hpp) and renamed into place; a failed encode, or a folder that cannot be written,
/// leaves no file, and its note says why (ffmpeg's exit status and first error line).
/// Without ffmpeg on PATH nothing is written and the note says so.
/// Throws std::invalid_argument unless fps > 0.
AnimationResult encode_animation(const std::filesystem::path& frame_pattern, double fps,
                                 const std::filesystem::path& mp4, const std::filesystem::path& gif);

/// Writes `player` (a gnuplot script) that plays frames 0 … count − 1 of `frame_pattern`
/// (relative to the script's folder, printf-style) at `fps` in a window:
/// `gnuplot -persist player`. A slide author can rerun it; --show starts it.
void write_player(const std::filesystem::path& player, const std::string& frame_pattern, long count,
                  double fps, int width, int height);

/// --show: starts the player in the background when a window can open (nothing waits for it),
/// and returns what happened, or why no window opened (no display, no window terminal).
std::string show_player(const std::filesystem::path& player);

}  // namespace kit
