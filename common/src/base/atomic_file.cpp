#include <kit/base/atomic_file.hpp>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <time.h>
#include <unistd.h>

namespace kit {
namespace {

// The temporaries in flight, in fixed storage that a signal handler may read: it calls only
// unlink(2), rmdir(2) and nanosleep(2), which are async-signal-safe. Slots are claimed and
// released by the main thread; a slot holds a file or a scratch folder.
constexpr std::size_t slots = 64, path_bytes = 4096;
enum SlotKind : std::sig_atomic_t { free_slot = 0, file_slot = 1, folder_slot = 2 };
std::array<std::array<char, path_bytes>, slots> in_flight{};
std::array<volatile std::sig_atomic_t, slots> occupied{};

// SIGPIPE too: a helper that exits before reading its whole script kills the chapter with it.
constexpr std::array<int, 4> cleanup_signals{SIGTERM, SIGINT, SIGHUP, SIGPIPE};
std::array<struct sigaction, 4> previous_actions{};

// Unlinks the files, then removes the folders. A helper still running may create a file in a
// folder between the two (rmdir then fails with ENOTEMPTY): unlink and try again, for at most
// about a second, after which a folder holding files nobody named is left as it is. (POSIX lets
// rmdir report a folder that is not empty as EEXIST too.)
void remove_temporaries() {
  for (int attempt = 0; attempt < 1000; ++attempt) {
    bool folder_left = false;
    for (std::size_t i = 0; i < slots; ++i)
      if (occupied[i] == file_slot) ::unlink(in_flight[i].data());
    for (std::size_t i = 0; i < slots; ++i)
      if (occupied[i] == folder_slot && ::rmdir(in_flight[i].data()) != 0 &&
          (errno == ENOTEMPTY || errno == EEXIST))
        folder_left = true;
    if (!folder_left) return;
    const struct timespec pause { 0, 1'000'000 };  // 1 ms: let the helper finish creating its file
    ::nanosleep(&pause, nullptr);
  }
}

// Removes the temporaries, then hands the signal to whoever handled it before (or to the
// default action, which ends the process).
extern "C" void remove_temporaries_and_die(int signal_number) {
  const int saved_errno = errno;  // a previous handler that returns must find errno as it was
  remove_temporaries();
  for (std::size_t k = 0; k < cleanup_signals.size(); ++k)
    if (cleanup_signals[k] == signal_number) sigaction(signal_number, &previous_actions[k], nullptr);
  std::raise(signal_number);
  errno = saved_errno;
}

// (Re)installs the handler when someone else's has replaced it (a test framework does per test).
void install_cleanup() {
  for (std::size_t k = 0; k < cleanup_signals.size(); ++k) {
    struct sigaction current {};
    sigaction(cleanup_signals[k], nullptr, &current);
    // Ours already, or ignored on purpose (nohup, a background job): leave it as it is.
    if (current.sa_handler == remove_temporaries_and_die || current.sa_handler == SIG_IGN) continue;
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_die;
    sigemptyset(&action.sa_mask);
    sigaction(cleanup_signals[k], &action, &previous_actions[k]);
  }
}

void remember(const std::filesystem::path& temporary, SlotKind kind = file_slot) {
  install_cleanup();
  const std::string text = temporary.string();
  if (text.size() >= path_bytes) return;  // too long to remember; still removed on failure
  for (std::size_t i = 0; i < slots; ++i)
    if (!occupied[i]) {
      std::memcpy(in_flight[i].data(), text.c_str(), text.size() + 1);
      std::atomic_signal_fence(std::memory_order_release);  // the path is whole before the flag says so
      occupied[i] = kind;
      return;
    }
}

// A test seam (tests/repo/interrupted_runs.py): with KIT_STOP_BEFORE_COMMIT=N in the
// environment, the process stops itself (SIGSTOP) just before its N-th commit, the temporary
// written and not yet in place. The test then signals it at a known point of its writing,
// rather than at whatever moment its polling of the folder happens to catch, which on a busy
// machine may come after the run has ended.
void stop_before_commit_if_asked() {
  static const long target = [] {
    const char* text = std::getenv("KIT_STOP_BEFORE_COMMIT");
    return text ? std::strtol(text, nullptr, 10) : 0L;
  }();
  static long commits = 0;
  if (target > 0 && ++commits == target) ::raise(SIGSTOP);
}

void forget(const std::filesystem::path& temporary) {
  const std::string text = temporary.string();
  for (std::size_t i = 0; i < slots; ++i)
    if (occupied[i] != free_slot && text == in_flight[i].data()) occupied[i] = free_slot;
}

}  // namespace

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
  auto temporary = path;
  temporary += fmt::format(".tmp-{}", ::getpid());
  remember(temporary);
  return temporary;
}

void discard_temporary(const std::filesystem::path& temporary) {
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
  forget(temporary);
}

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  const auto temporary = temporary_sibling(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.close();
    if (!out) {
      discard_temporary(temporary);
      throw std::runtime_error(fmt::format("cannot write {}", path.string()));
    }
  }
  commit_file(temporary, path);
}

void commit_file(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  stop_before_commit_if_asked();
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  forget(temporary);
  if (error) {
    discard_temporary(temporary);
    throw std::runtime_error(fmt::format("cannot move {} into place: {}", path.string(), error.message()));
  }
}

ScratchFolder::ScratchFolder(const std::filesystem::path& beside) : path_(beside) {
  path_ += fmt::format(".tmp-{}.d", ::getpid());
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);  // a leftover of an earlier process with this pid
  remember(path_, folder_slot);
  std::error_code error;
  std::filesystem::create_directory(path_, error);
  if (error) {
    forget(path_);
    throw std::runtime_error(fmt::format("cannot create the folder {}: {}", path_.string(), error.message()));
  }
}

std::filesystem::path ScratchFolder::file(const std::string& name) {
  files_.push_back(path_ / name);
  remember(files_.back());
  return files_.back();
}

ScratchFolder::~ScratchFolder() {
  for (const auto& file : files_) discard_temporary(file);
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
  forget(path_);
}

}  // namespace kit
