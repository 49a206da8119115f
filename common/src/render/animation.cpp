#include <kit/render/animation.hpp>

#include <kit/app/figure.hpp>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <kit/base/atomic_file.hpp>

extern char** environ;

namespace kit {
namespace {

// How one ffmpeg run ended: ok, or a sentence saying how it failed.
struct RunOutcome {
  bool ok = false;
  std::string failure;
};

std::string first_line_of(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) return line;
  return {};
}

// The argv of a spawned program: pointers into `words`, ended by a null pointer.
std::vector<char*> argv_of(std::vector<std::string>& words) {
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  return argv;
}

// Runs ffmpeg with `arguments` (argv[1..]) without a shell: stdin /dev/null, stdout and stderr
// into `log`. Waits for it.
RunOutcome run_ffmpeg(const std::filesystem::path& ffmpeg, const std::vector<std::string>& arguments,
                      const std::filesystem::path& log) {
  std::vector<std::string> words{ffmpeg.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv = argv_of(words);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t child = 0;
  const int spawn_error = posix_spawn(&child, ffmpeg.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error != 0)
    return {false, fmt::format("could not start {}: {}", ffmpeg.string(), std::strerror(spawn_error))};

  int status = 0;
  while (::waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return {false, fmt::format("lost track of ffmpeg: {}", std::strerror(errno))};
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {true, {}};
  std::string how = WIFEXITED(status) ? fmt::format("exit status {}", WEXITSTATUS(status))
                                      : fmt::format("killed by signal {}", WTERMSIG(status));
  const std::string message = first_line_of(log);
  if (!message.empty()) how += ": " + message;
  return {false, how};
}

// One video: ffmpeg writes into a private folder that a signal removes (so an ffmpeg that
// outlives a SIGTERM sent to the chapter alone cannot leave its file behind), with its muxer
// named by -f; the file is renamed onto `path` only when ffmpeg succeeded.
RunOutcome encode_one(const std::filesystem::path& ffmpeg, std::vector<std::string> arguments,
                      const char* muxer, const std::filesystem::path& path) {
  std::optional<ScratchFolder> scratch_holder;
  try {
    scratch_holder.emplace(path);
  } catch (
      const std::runtime_error& error) {  // an output folder that cannot be written: a note, as for ffmpeg
    return {false, error.what()};
  }
  ScratchFolder& scratch = *scratch_holder;
  const auto log = scratch.file(path.filename().string() + ".ffmpeg-log");
  const auto temporary = scratch.file(path.filename().string());
  arguments.insert(arguments.end(), {"-f", muxer, temporary.string()});
  RunOutcome outcome = run_ffmpeg(ffmpeg, arguments, log);
  discard_temporary(log);
  if (outcome.ok) {
    std::error_code error;
    if (std::filesystem::file_size(temporary, error) == 0 || error)
      outcome = {false, "ffmpeg wrote an empty file"};
  }
  if (!outcome.ok) {
    discard_temporary(temporary);
    return outcome;
  }
  try {
    commit_file(temporary, path);
  } catch (const std::runtime_error& error) {
    return {false, error.what()};
  }
  return outcome;
}

}  // namespace

std::filesystem::path find_ffmpeg() {
  const char* path_variable = std::getenv("PATH");
  if (!path_variable) return {};
  std::string_view rest(path_variable);
  while (true) {
    const auto colon = rest.find(':');
    const std::string_view folder = rest.substr(0, colon);
    // An empty entry means the current folder, as for the shell.
    const std::filesystem::path candidate =
        std::filesystem::path(folder.empty() ? "." : std::string(folder)) / "ffmpeg";
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    if (colon == std::string_view::npos) return {};
    rest.remove_prefix(colon + 1);
  }
}

AnimationResult encode_animation(const std::filesystem::path& frame_pattern, double fps,
                                 const std::filesystem::path& mp4, const std::filesystem::path& gif) {
  if (!(fps > 0)) throw std::invalid_argument(fmt::format("encode_animation needs fps > 0, not {}", fps));
  const std::string frames_folder =
      frame_pattern.parent_path().empty() ? "." : frame_pattern.parent_path().string();
  const std::filesystem::path ffmpeg = find_ffmpeg();
  if (ffmpeg.empty())
    return {
        {},
        fmt::format(
            "ffmpeg not found: install it (./kit deps) for the MP4 and GIF; the PNG frames are kept in {}",
            frames_folder)};

  const std::vector<std::string> input{"-nostdin", "-loglevel",           "error",
                                       "-y",       "-framerate",          fmt::format("{}", fps),
                                       "-i",       frame_pattern.string()};
  AnimationResult result;
  std::vector<std::string> failures;

  auto mp4_arguments = input;
  // yuv420p stores colour at half resolution, so libx264 needs even sizes: pad by one pixel.
  mp4_arguments.insert(mp4_arguments.end(),
                       {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p"});
  if (const RunOutcome outcome = encode_one(ffmpeg, mp4_arguments, "mp4", mp4); outcome.ok)
    result.files.push_back(mp4);
  else
    failures.push_back(fmt::format("ffmpeg could not make {} ({})", mp4.string(), outcome.failure));

  auto gif_arguments = input;
  // GIF holds 256 colours: one palette computed from the whole clip, then applied to each frame.
  gif_arguments.insert(gif_arguments.end(),
                       {"-filter_complex", "[0:v]split[a][b];[a]palettegen[p];[b][p]paletteuse"});
  if (const RunOutcome outcome = encode_one(ffmpeg, gif_arguments, "gif", gif); outcome.ok)
    result.files.push_back(gif);
  else
    failures.push_back(fmt::format("ffmpeg could not make {} ({})", gif.string(), outcome.failure));

  if (!failures.empty())
    result.note = fmt::format("{}; the PNG frames are kept in {}", fmt::join(failures, "; "), frames_folder);
  return result;
}

void write_player(const std::filesystem::path& player, const std::string& frame_pattern, long count,
                  double fps, int width, int height) {
  write_file_atomic(
      player,
      fmt::format("# Plays the frames of this folder in a window: gnuplot -persist {0}\n"
                  "unset key; unset border; unset tics; set margins 0,0,0,0; set size ratio {1}.0/{2}\n"
                  "do for [i = 0:{3}] {{\n"
                  "  plot sprintf('{4}', i) binary filetype=png with rgbimage\n"
                  "  pause {5}\n"
                  "}}\n",
                  player.filename().string(), height, width, count - 1, frame_pattern, 1.0 / fps));
}

std::string show_player(const std::filesystem::path& player) {
  if (const auto why = window_unavailable()) return fmt::format("--show: {}; the frames are written", *why);
  std::vector<std::string> words{"gnuplot", "-persist", player.filename().string()};
  std::vector<char*> argv = argv_of(words);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addchdir_np(&actions, player.parent_path().c_str());
  pid_t child = 0;  // not waited for: the window outlives the chapter
  const int error = posix_spawnp(&child, "gnuplot", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) return fmt::format("--show: could not start gnuplot: {}", std::strerror(error));
  return fmt::format("--show: playing the frames in a gnuplot window ({})", player.string());
}

}  // namespace kit
