#pragma once
// A chapter binary run for its numbers: --json --no-plot into a temporary --out, the exit code
// required (its stderr shown when it differs), stdout parsed.
#include <string>
#include <vector>

#include <kit_catch.hpp>
#include <nlohmann/json.hpp>

#include "process.hpp"

namespace kit::test {

inline nlohmann::json run_chapter_json(const std::string& binary, std::vector<std::string> args, const std::string& tag,
                                       int expected_exit = 0) {
  TempDir out(tag);
  args.insert(args.end(), {"--json", "--no-plot", "--out", out.path().string()});
  const auto result = run_process(binary, args);
  INFO(result.err);
  REQUIRE(result.exit_code == expected_exit);
  return nlohmann::json::parse(result.out);
}

}  // namespace kit::test
