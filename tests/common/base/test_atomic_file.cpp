#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include <kit_catch.hpp>

#include <kit/base/atomic_file.hpp>

#include "process.hpp"

TEST_CASE("an atomic write leaves exactly the final file, with the whole content") {
  kit::test::TempDir dir("atomic");
  const auto path = dir.path() / "out.txt";
  kit::write_file_atomic(path, "first");
  kit::write_file_atomic(path, "second, longer");
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  CHECK(text.str() == "second, longer");
  CHECK(kit::test::files_under(dir.path()).size() == 1);
}

TEST_CASE("a write that cannot happen throws, naming the path, and leaves nothing") {
  kit::test::TempDir dir("atomic-fail");
  const auto path = dir.path() / "missing-folder" / "out.txt";
  CHECK_THROWS_WITH(kit::write_file_atomic(path, "x"), ContainsSubstring("missing-folder"));
  CHECK(kit::test::files_under(dir.path()).empty());
}

TEST_CASE("a process killed by SIGTERM while a file is half-written leaves no temporary behind") {
  kit::test::TempDir dir("atomic-signal");
  const auto path = dir.path() / "figure.png";
  const pid_t child = ::fork();
  if (child == 0) {                 // the child starts a write, as a render in progress, then is terminated
    std::signal(SIGTERM, SIG_DFL);  // as in a chapter binary: no test framework's handler
    const auto temporary = kit::temporary_sibling(path);
    std::ofstream(temporary) << "half a figure";
    ::kill(::getpid(), SIGTERM);
    ::_exit(0);  // not reached
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  CHECK(WIFSIGNALED(status));
  CHECK(WTERMSIG(status) == SIGTERM);
  CHECK(kit::test::files_under(dir.path()).empty());
}

namespace {
bool folder_is_empty(const std::filesystem::path& folder) {
  return std::filesystem::directory_iterator(folder) == std::filesystem::directory_iterator();
}
}  // namespace

TEST_CASE("a scratch folder holds a helper's files until they are committed, and goes away after") {
  kit::test::TempDir dir("scratch");
  const auto final_path = dir.path() / "figure.pdf";
  {
    kit::ScratchFolder scratch(dir.path() / "figure");
    CHECK(scratch.path().parent_path() == dir.path());
    CHECK(scratch.path().filename().string().find(".tmp-") != std::string::npos);
    const auto output = scratch.file("figure.pdf"), log = scratch.file("figure.log");
    CHECK(output.parent_path() == scratch.path());
    std::ofstream(output) << "a figure";
    std::ofstream(log) << "a helper's messages";
    kit::commit_file(output, final_path);
  }
  REQUIRE(kit::test::files_under(dir.path()).size() == 1);
  CHECK(std::filesystem::exists(final_path));
  CHECK(std::distance(std::filesystem::directory_iterator(dir.path()),
                      std::filesystem::directory_iterator()) == 1);
}

TEST_CASE("a helper that outlives a SIGTERM to its parent finds no scratch folder to write into") {
  kit::test::TempDir dir("scratch-signal");
  int helper_done[2];
  REQUIRE(::pipe(helper_done) == 0);
  const pid_t child = ::fork();
  if (child == 0) {  // the chapter: it starts a helper that writes late, then is terminated
    std::signal(SIGTERM, SIG_DFL);
    kit::ScratchFolder scratch(dir.path() / "figure");
    const auto output = scratch.file("figure.pdf");
    std::ofstream(scratch.file("figure.log")) << "the helper's log, already open";
    if (::fork() == 0) {  // the helper: not signalled; it writes after its parent has died
      ::close(helper_done[0]);
      ::usleep(300'000);
      const bool wrote = static_cast<bool>(std::ofstream(output) << "a figure too late");
      const char verdict = wrote ? 'w' : 'n';
      (void)!::write(helper_done[1], &verdict, 1);
      ::_exit(0);
    }
    ::kill(::getpid(), SIGTERM);
    ::_exit(0);  // not reached
  }
  ::close(helper_done[1]);
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  CHECK(WIFSIGNALED(status));
  char verdict = '?';
  REQUIRE(::read(helper_done[0], &verdict, 1) == 1);  // waits for the helper's attempt
  ::close(helper_done[0]);
  CHECK(verdict == 'n');
  CHECK(folder_is_empty(dir.path()));
}
