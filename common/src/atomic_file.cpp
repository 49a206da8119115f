#include <kit/atomic_file.hpp>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

namespace kit {
namespace {

// The temporaries in flight, in fixed storage that a signal handler may read: it calls only
// unlink(2), which is async-signal-safe. Slots are claimed and released by the main thread.
constexpr std::size_t slots = 64, path_bytes = 4096;
std::array<std::array<char, path_bytes>, slots> in_flight{};
std::array<volatile std::sig_atomic_t, slots> occupied{};

constexpr std::array<int, 3> cleanup_signals{SIGTERM, SIGINT, SIGHUP};
std::array<struct sigaction, 3> previous_actions{};

// Removes the temporaries, then hands the signal to whoever handled it before (or to the
// default action, which ends the process).
extern "C" void remove_temporaries_and_die(int signal_number) {
  for (std::size_t i = 0; i < slots; ++i)
    if (occupied[i]) ::unlink(in_flight[i].data());
  for (std::size_t k = 0; k < cleanup_signals.size(); ++k)
    if (cleanup_signals[k] == signal_number) sigaction(signal_number, &previous_actions[k], nullptr);
  std::raise(signal_number);
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

void remember(const std::filesystem::path& temporary) {
  install_cleanup();
  const std::string text = temporary.string();
  if (text.size() >= path_bytes) return;  // too long to remember; still removed on failure
  for (std::size_t i = 0; i < slots; ++i)
    if (!occupied[i]) {
      std::memcpy(in_flight[i].data(), text.c_str(), text.size() + 1);
      std::atomic_signal_fence(std::memory_order_release);  // the path is whole before the flag says so
      occupied[i] = 1;
      return;
    }
}

void forget(const std::filesystem::path& temporary) {
  const std::string text = temporary.string();
  for (std::size_t i = 0; i < slots; ++i)
    if (occupied[i] && text == in_flight[i].data()) occupied[i] = 0;
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
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  forget(temporary);
  if (error) {
    discard_temporary(temporary);
    throw std::runtime_error(fmt::format("cannot move {} into place: {}", path.string(), error.message()));
  }
}

}  // namespace kit
