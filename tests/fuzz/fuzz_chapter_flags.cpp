// libFuzzer target: one chapter's command line, linked with that chapter's main.cpp (compiled
// with main renamed kit_chapter_main). The input is the argument list, one argument per line.
// The chapter parses and range-checks its flags and returns before computing anything
// (ChapterApp::parse_only_for_fuzzing): the only right answers are 0 and 2, with a message.
//
// With KIT_FUZZ_SEEDS=DIR set, start-up first writes seed inputs into DIR from the chapter's
// own flag table: each flag at its default and at both ends of its range.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <kit/app/chapter_app.hpp>

int kit_chapter_main(int argc, char** argv);

namespace {

int run_chapter(std::vector<std::string> words) {
  words.insert(words.begin(), "chapter");
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  return kit_chapter_main(int(words.size()), argv.data());
}

// Seeds from the chapter's --flag-table (printed on std::cout, captured here).
void write_seeds(const std::string& dir) {
  std::ostringstream captured;
  auto* const saved = std::cout.rdbuf(captured.rdbuf());
  run_chapter({"--flag-table"});
  std::cout.rdbuf(saved);
  int n = 0;
  const auto seed = [&](const std::string& text) {
    std::ofstream(fmt::format("{}/seed-{:03}", dir, n++)) << text;
  };
  seed("--help");
  seed("--json\n--no-plot");
  for (const auto& flag : nlohmann::json::parse(captured.str())) {
    const std::string name = flag["flag"];
    for (const char* key : {"default", "lo", "hi"}) {
      const double value = flag[key];
      if (std::isfinite(value)) seed(fmt::format("{}\n{}", name, value));
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("KIT_FUZZ_SEEDS")) write_seeds(dir);
  kit::ChapterApp::parse_only_for_fuzzing();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> words(1);
  for (std::size_t i = 0; i < size && words.size() <= 64; ++i) {
    if (data[i] == '\n')
      words.emplace_back();
    else
      words.back().push_back(char(data[i]));
  }
  const int code = run_chapter(words);
  if (code != 0 && code != 2) {
    std::cerr << "exit " << code << ": valid input must run (0) and bad input be refused (2)\n";
    std::abort();
  }
  return 0;
}
