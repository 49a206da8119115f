#include <csignal>

#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>

#include <kit/atomic_file.hpp>

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
  CHECK_THROWS_WITH(kit::write_file_atomic(path, "x"), Catch::Contains("missing-folder"));
  CHECK(kit::test::files_under(dir.path()).empty());
}

TEST_CASE("a process killed by SIGTERM while a file is half-written leaves no temporary behind") {
  kit::test::TempDir dir("atomic-signal");
  const auto path = dir.path() / "figure.png";
  const pid_t child = ::fork();
  if (child == 0) {  // the child starts a write, as a render in progress, then is terminated
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
