#pragma once
// A chapter binary run for its --json summary, written once for the nine chapter tests: each used
// to keep its own copy, and the copies drifted apart in which flags they added and in what they
// showed when the exit code was wrong.
#include <filesystem>
#include <string>
#include <vector>

#include <kit_catch.hpp>
#include <nlohmann/json.hpp>

#include "process.hpp"

namespace kit::test {

/// The process as it ended (exit code, stdout, stderr) and its stdout parsed: a test that checks
/// stderr as well as the numbers (no gnuplot warning) needs both.
struct ChapterRun {
  ProcessResult process;
  nlohmann::json summary;
};

/// Runs `binary` with exactly `args` (which ask for --json), requires `expected_exit` with its
/// stderr shown when it differs, and parses stdout. The overloads below add the usual flags.
inline ChapterRun run_chapter(const std::string& binary, const std::vector<std::string>& args,
                              int expected_exit = 0) {
  ChapterRun run{run_process(binary, args), {}};
  INFO(run.process.err);
  REQUIRE(run.process.exit_code == expected_exit);
  run.summary = nlohmann::json::parse(run.process.out);
  return run;
}

/// For the numbers alone: `args` then --json --no-plot --out into a temporary folder named after
/// `tag`, removed on return, so no figure is drawn and no file is left.
inline nlohmann::json run_chapter_json(const std::string& binary, std::vector<std::string> args,
                                       const std::string& tag, int expected_exit = 0) {
  TempDir out(tag);
  args.insert(args.end(), {"--json", "--no-plot", "--out", out.path().string()});
  return run_chapter(binary, args, expected_exit).summary;
}

/// For the numbers and the files: `args` then --json --out `out`, figures on unless `args` say
/// --no-plot, into a folder the caller keeps to look at. A name of its own, not an overload of
/// run_chapter_json: a string literal converts to both std::string and std::filesystem::path.
inline nlohmann::json run_chapter_into(const std::string& binary, std::vector<std::string> args,
                                       const std::filesystem::path& out, int expected_exit = 0) {
  args.insert(args.end(), {"--json", "--out", out.string()});
  return run_chapter(binary, args, expected_exit).summary;
}

}  // namespace kit::test
