#pragma once
// One chapter binary: its flags (CLI11), where its text, JSON summary and figures go, and how
// it ends. CLI11 stays out of this header: it is header-only, and every file that includes it
// compiles its parser, help formatter and config reader again (about 4 s a file at -O3, in each
// chapter's main.cpp of each tree the tests build). Library code that adds its own options
// includes <CLI/CLI.hpp> and uses cli(). The conventions every chapter shares:
//  - physical parameters are flags with SI units in their help and a stated allowed range;
//  - bad input is a usage error: the message names the flag, the value and the range, the
//    exit code is 2 and nothing is written;
//  - --json prints one summary object on stdout and nothing else;
//  - a diverging simulation is a reported result (exit 0, or 3 under --fail-on-divergence).
#include <functional>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include <kit/app/figure.hpp>
#include <kit/app/progress.hpp>
#include <kit/app/report.hpp>
#include <kit/base/real_range.hpp>
#include <kit/base/usage.hpp>

namespace CLI {
class App;
}  // namespace CLI

namespace kit {

/// Checks that `dir` is, or can be created as, a writable folder (creating nothing); a
/// UsageError naming --out otherwise. Chapters call it (through run) before computing anything.
void check_output_folder(const std::string& dir);

/// The flags every chapter shares.
struct CommonOptions {
  std::string out_dir;                             ///< --out: where figures go
  std::vector<std::string> formats{"pdf", "png"};  ///< --format
  bool no_plot = false;                            ///< --no-plot: compute and print only
  bool show = false;                               ///< --show: open a window if a display exists
  bool json = false;                               ///< --json: one JSON object on stdout
  bool quiet = false;                              ///< --quiet: no text on stdout
  std::string summary_file;                        ///< --summary: the JSON summary to a file too
  bool fail_on_divergence = false;                 ///< --fail-on-divergence: exit 3 if a run diverged
  bool quick = false;                              ///< --quick: the lecture's experiments at reduced sizes
  bool no_viewer = false;                          ///< --no-viewer: no 3D page beside the frames
};

/// One chapter binary: its flags, its text and JSON report, and its figures.
class ChapterApp {
 public:
  ChapterApp(std::string chapter, std::string default_out_dir, std::string description);
  ~ChapterApp();
  ChapterApp(const ChapterApp&) = delete;
  ChapterApp& operator=(const ChapterApp&) = delete;

  /// A real-valued flag stored into `value` (whose initial value is the default). `help`
  /// names the quantity and its SI unit; `range` is enforced at parse time.
  void add_real(const std::string& flag, double& value, const std::string& help, RealRange range);
  /// A whole-number flag in [lo, hi].
  void add_count(const std::string& flag, long& value, const std::string& help, long lo, long hi);
  /// A flag that takes one of `choices` (names, such as a problem or a method), stored into `value`
  /// (whose initial value is the default); any other value is a usage error naming them.
  void add_choice(const std::string& flag, std::string& value, const std::string& help,
                  const std::vector<std::string>& choices);
  /// The parser itself, for options of other kinds; include <CLI/CLI.hpp> to use it.
  CLI::App& cli() { return *app_; }

  /// Parses the flags and runs `body`. Returns the exit code: 0 after --help or success,
  /// 2 on a usage error (message on stderr, nothing written), 1 on another failure.
  int run(int argc, const char* const* argv, const std::function<void()>& body);

  /// For the flag fuzzers (tests/fuzz/fuzz_chapter_flags.cpp) only: from then on, run() parses
  /// the flags, checks their ranges and records them, and returns before the body (0 or 2).
  static void parse_only_for_fuzzing();

  const CommonOptions& options() const { return options_; }
  /// Human-readable output: stdout, or nowhere under --json or --quiet. Each write first erases
  /// the progress line, which the next report of work draws again below the text.
  std::ostream& text();
  /// The summary printed by --json. "chapter" and "parameters" are filled in already.
  nlohmann::json& summary() { return summary_; }
  /// Text and JSON from one call (report.hpp): what chapters print their numbers through.
  Report& report() { return report_; }
  /// Writes a figure under --out (data and script always; renders unless --no-plot) and
  /// lists its files in the summary.
  void figure(const Figure& figure);

  /// Runs one section of the lecture, `fn()`, or says which exercise it waits for
  /// (Report::attempt): a student sees every section that their code already runs. While it
  /// runs, the progress line on a terminal (progress.hpp) names it.
  template <class F>
  auto section(const std::string& title, F&& fn) {
    const ProgressTask progress(title);
    return report_.attempt(title, std::forward<F>(fn));
  }
  /// The same for a section that draws `figures`: when it, or a part of it, waits for an exercise
  /// before drawing one of them, the summary lists the ones not drawn under "figures_waiting".
  template <class F>
  auto section(const std::string& title, const std::vector<std::string>& figures, F&& fn) {
    const auto skipped = [&] { return summary_.contains("skipped") ? summary_["skipped"].size() : 0; };
    const std::size_t skipped_before = skipped();
    auto result = section(title, std::forward<F>(fn));
    if (skipped() > skipped_before && !options_.no_plot)
      for (const auto& name : figures)
        if (!summary_["figures"].contains(name)) summary_["figures_waiting"].push_back(name);
    return result;
  }

  /// Adds --fail-on-divergence, for chapters whose runs can blow up.
  void add_divergence_flag();
  /// Adds --quick, for chapters whose fixed experiments take seconds: `sizes` says what it shrinks
  /// ("the resolution sweeps stop at N = 32", say). Every section still runs, on the scene and
  /// flags given, so a quick run shows the same behaviour in a fraction of the time; the summary
  /// records "quick": true, and the figures hold fewer points.
  void add_quick_flag(const std::string& sizes);
  /// --no-viewer (chapters that write frames): leave out the 3D page (write_page, page_output.hpp).
  void add_viewer_flag();
  /// Records that a run diverged: a result, listed under "divergences" in the summary. The
  /// chapter still finishes and exits 0, or 3 under --fail-on-divergence.
  void diverged(const std::string& run, const std::string& what);

 private:
  std::string chapter_;
  std::unique_ptr<CLI::App> app_;
  CommonOptions options_;
  nlohmann::json summary_;
  std::vector<std::function<void()>> record_parameters_;
  std::ostream null_{nullptr};
  std::unique_ptr<std::streambuf> stdout_buffer_;  // stdout that first erases the progress line
  std::ostream stdout_{nullptr};
  Report report_{null_, summary_};                       // bound to text() once the flags are parsed
  nlohmann::json flag_table_ = nlohmann::json::array();  // every numeric flag and its range
  bool flag_table_requested_ = false;
};

}  // namespace kit
