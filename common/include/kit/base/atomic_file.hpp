#pragma once
// Files appear whole or not at all: write a temporary sibling, then rename it into place.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace kit {

/// A temporary name next to `path` ("name.ext.tmp-<pid>"), on the same file system, so the
/// final rename is atomic. The name is remembered until commit_file or discard_temporary: a
/// SIGTERM, SIGINT, SIGHUP or SIGPIPE (a timeout, Ctrl-C, a closed terminal, a helper or reader
/// gone) removes every remembered temporary before the process dies, so an interrupted run
/// leaves no half-written file.
std::filesystem::path temporary_sibling(const std::filesystem::path& path);
/// Removes a temporary that will not be committed (ignoring a missing file) and forgets it.
void discard_temporary(const std::filesystem::path& temporary);

/// Writes `content` to `path` through a temporary sibling. Throws std::runtime_error naming
/// the path when the write fails; no partial file is left behind.
void write_file_atomic(const std::filesystem::path& path, std::string_view content);

/// Renames a finished temporary file onto its final name. For tests, KIT_STOP_BEFORE_COMMIT=N
/// in the environment makes the process stop itself (SIGSTOP) before its N-th commit.
void commit_file(const std::filesystem::path& temporary, const std::filesystem::path& path);

/// A private folder next to `beside` ("name.tmp-<pid>.d") for a helper program (gnuplot,
/// ffmpeg) to write its output and log into. A helper can outlive the process: a SIGTERM sent
/// to the chapter alone does not reach it. So a signal removes the folder's files, named here
/// by `file`, and then the folder itself, repeating until the folder is gone; a helper that
/// writes afterwards finds no folder and cannot leave a file behind. The destructor removes
/// whatever is still inside.
class ScratchFolder {
 public:
  explicit ScratchFolder(const std::filesystem::path& beside);
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// The path of `name` inside the folder, removed by a signal from now on.
  std::filesystem::path file(const std::string& name);

 private:
  std::filesystem::path path_;
  std::vector<std::filesystem::path> files_;
};

}  // namespace kit
