#pragma once
// Runs a chapter binary as a user would, capturing its exit code, stdout and stderr.
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace kit::test {

struct ProcessResult {
  int exit_code = -1;
  std::string out, err;
};

inline std::string shell_quote(const std::string& word) {
  std::string quoted = "'";
  for (char c : word) quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

/// Runs `program args...` through /bin/sh, without a display, and waits for it.
inline ProcessResult run_process(const std::string& program, const std::vector<std::string>& args) {
  const auto err_file =
      std::filesystem::temp_directory_path() / ("kit-test-stderr-" + std::to_string(::getpid()));
  // Appends only: `"literal" + std::string` trips GCC 12's false -Wrestrict at -O3 (PR 105651).
  std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY ";
  command += shell_quote(program);
  for (const auto& arg : args) {
    command += ' ';
    command += shell_quote(arg);
  }
  command += " 2>";
  command += shell_quote(err_file.string());
  ProcessResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream err(err_file);
  std::stringstream text;
  text << err.rdbuf();
  result.err = text.str();
  std::filesystem::remove(err_file);
  return result;
}

/// A fresh, empty folder under the system temporary folder, removed at scope exit.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    path_ = std::filesystem::temp_directory_path() /
            ("kit-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter()++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  static int& counter() {
    static int n = 0;
    return n;
  }
  std::filesystem::path path_;
};

/// The whole file at `path`, as bytes; "" when it cannot be read.
inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// Files (not folders) under `dir`, recursively; empty when `dir` does not exist.
inline std::vector<std::filesystem::path> files_under(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::exists(dir)) return files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
    if (entry.is_regular_file()) files.push_back(entry.path());
  return files;
}

/// A bad command line and the text its error message must contain (the offending flag).
struct BadInput {
  std::vector<std::string> args;
  std::string names;
};

/// Each bad input must exit 2, name the flag on stderr, print nothing on stdout, and leave the
/// --out folder uncreated.
void expect_usage_errors(const std::string& binary, const std::vector<BadInput>& cases);

}  // namespace kit::test
