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
