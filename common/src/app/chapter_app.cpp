#include <kit/app/chapter_app.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include <unistd.h>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <kit/base/atomic_file.hpp>
#include <kit/base/whole_number.hpp>

namespace kit {

namespace {
bool parse_only = false;  // set by the flag fuzzers (parse_only_for_fuzzing)

/// Writes to `target`, but first erases the progress line from the terminal, so that the
/// chapter's text and the line never mix.
class ClearingBuffer : public std::streambuf {
 public:
  explicit ClearingBuffer(std::streambuf* target) : target_(target) {}

 protected:
  int overflow(int c) override {
    ProgressTask::clear_line();
    return c == traits_type::eof() ? traits_type::not_eof(c) : target_->sputc(traits_type::to_char_type(c));
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    ProgressTask::clear_line();
    return target_->sputn(s, n);
  }
  int sync() override { return target_->pubsync(); }

 private:
  std::streambuf* target_;
};
}  // namespace

// A refusal naming `flag` and its `value` unless this process may create files in `folder`.
void require_writable(const std::string& flag, const std::string& value,
                      const std::filesystem::path& folder) {
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw UsageError(fmt::format("{} '{}': {} is not writable", flag, value, folder.string()));
}

void check_output_folder(const std::string& dir) {
  namespace fs = std::filesystem;
  if (dir.empty()) throw UsageError("--out '': expected a folder name (or --no-plot to write no figure)");
  // Nothing is created here (a refused run leaves no trace): the folder, or the nearest part of
  // its path that exists, must be a folder this process may write into.
  std::error_code error;
  fs::path existing = fs::absolute(dir, error);
  while (!existing.empty() && !fs::exists(existing, error) && existing != existing.parent_path())
    existing = existing.parent_path();
  if (!fs::is_directory(existing, error))
    throw UsageError(fmt::format("--out '{}': {} is a file, not a folder", dir, existing.string()));
  require_writable("--out", dir, existing);
}

// --summary FILE: the file itself is written at the end, through a temporary; here its folder
// must exist and be writable and FILE must not be a folder, so that a refused run costs nothing.
void check_summary_file(const std::string& file) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path path = fs::absolute(file, error);
  if (file.empty() || path.filename().empty())
    throw UsageError(fmt::format("--summary '{}': expected a file name", file));
  if (fs::is_directory(path, error))
    throw UsageError(fmt::format("--summary '{}': a folder, not a file", file));
  const fs::path folder = path.parent_path();
  if (!fs::is_directory(folder, error))
    throw UsageError(fmt::format("--summary '{}': the folder {} does not exist", file, folder.string()));
  require_writable("--summary", file, folder);
}

ChapterApp::ChapterApp(std::string chapter, std::string default_out_dir, std::string description)
    : chapter_(std::move(chapter)), app_(std::make_unique<CLI::App>(std::move(description), chapter_)) {
  options_.out_dir = std::move(default_out_dir);
  app_->option_defaults()->always_capture_default();
  app_->get_formatter()->column_width(34);
  app_->add_option("--out", options_.out_dir, "folder for the figures (data, gnuplot script, renders)")
      ->type_name("DIR");
  app_->add_option("--format", options_.formats, "renders to write, comma-separated: pdf, png, svg")
      ->delimiter(',')
      ->type_name("LIST")
      ->check(CLI::IsMember({"pdf", "png", "svg"}));
  app_->add_flag("--no-plot", options_.no_plot, "write no figure files at all");
  app_->add_flag("--show", options_.show, "also open each figure in a window when a display exists");
  app_->add_flag("--json", options_.json, "print one JSON summary object on stdout, and nothing else");
  app_->add_flag("--quiet", options_.quiet, "print nothing on stdout");
  app_->add_option("--summary", options_.summary_file,
                   "also write the JSON summary (as --json prints it) to FILE, whatever stdout shows")
      ->type_name("FILE");
  // For the flag-table test: every numeric flag with its range, as JSON; not in --help.
  app_->add_flag("--flag-table", flag_table_requested_, "")->group("");
  summary_["chapter"] = chapter_;
  stdout_buffer_ = std::make_unique<ClearingBuffer>(std::cout.rdbuf());
  stdout_.rdbuf(stdout_buffer_.get());
}

ChapterApp::~ChapterApp() = default;

void ChapterApp::add_real(const std::string& flag, double& value, const std::string& help, RealRange range) {
  auto check = [flag, range](std::string& input) -> std::string {
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(input.c_str(), &end);
    if (end == input.c_str() || *end != '\0')
      return fmt::format("'{}' is not a number; expected {}", input, range.describe());
    if (errno == ERANGE || !range.contains(v))
      return fmt::format("value {} is out of range; expected {}", input, range.describe());
    return {};
  };
  app_->add_option(flag, value, fmt::format("{}; {}", help, range.describe()))
      ->check(CLI::Validator(check, "", ""))
      ->type_name("REAL");
  const std::string key = flag.substr(flag.find_first_not_of('-'));
  record_parameters_.push_back([this, key, &value] { summary_["parameters"][key] = value; });
  flag_table_.push_back({{"flag", flag},
                         {"kind", "real"},
                         {"default", value},
                         {"lo", range.lo},
                         {"hi", range.hi},
                         {"lo_open", range.lo_open},
                         {"hi_open", range.hi_open},
                         {"nonzero", range.nonzero}});
}

void ChapterApp::add_choice(const std::string& flag, std::string& value, const std::string& help,
                            const std::vector<std::string>& choices) {
  // --help shows the default: the constructor set always_capture_default() for every option.
  app_->add_option(flag, value, help)->check(CLI::IsMember(choices))->type_name("NAME");
}

void ChapterApp::add_count(const std::string& flag, long& value, const std::string& help, long lo, long hi) {
  auto check = [lo, hi](std::string& input) -> std::string {
    using Kind = WholeNumberText::Kind;
    const WholeNumberText read = read_whole_number(input);
    const std::string expected = fmt::format("expected a whole number in [{}, {}]", lo, hi);
    switch (read.kind) {
      case Kind::not_a_number:
        return fmt::format("value {} is not a number; {}", input, expected);
      case Kind::not_whole:
        return fmt::format("value {} is not a whole number; {}", input, expected);
      case Kind::leading_zero:
        return fmt::format("value {} starts with 0, which some tools read as octal; {}", input, expected);
      case Kind::too_large:
        return fmt::format("value {} is out of range; {}", input, expected);
      case Kind::whole:
        break;
    }
    if (read.value < lo || read.value > hi)
      return fmt::format("value {} is out of range; {}", input, expected);
    input = fmt::format("{}", read.value);  // CLI11 then reads plain digits: "1e9" arrives as 1000000000
    return {};
  };
  app_->add_option(flag, value, fmt::format("{}; a whole number in [{}, {}]", help, lo, hi))
      ->transform(CLI::Validator(check, "", ""))  // a transform: it may rewrite "1e9" in digits
      ->type_name("N");
  const std::string key = flag.substr(flag.find_first_not_of('-'));
  record_parameters_.push_back([this, key, &value] { summary_["parameters"][key] = value; });
  flag_table_.push_back({{"flag", flag}, {"kind", "count"}, {"default", value}, {"lo", lo}, {"hi", hi}});
}

std::ostream& ChapterApp::text() { return (options_.json || options_.quiet) ? null_ : stdout_; }

void ChapterApp::figure(const Figure& fig) {
  if (options_.no_plot) return;
  // A figure with no data at all (every method it draws waits for its exercise) is not drawn:
  // the text says so, and the summary lists it under "figures_waiting".
  const auto has_data = [](const Panel& panel) {
    return std::any_of(panel.series.begin(), panel.series.end(),
                       [](const Series& s) { return !s.x.empty(); });
  };
  if (std::none_of(fig.panels.begin(), fig.panels.end(), has_data)) {
    report_.print(
        fmt::format("[skipped] figure {}: no data to draw (its methods wait for their exercises, or the "
                    "run gave none)\n",
                    fig.name));
    summary_["figures_waiting"].push_back(fig.name);
    return;
  }
  FigureOptions figure_options;
  figure_options.dir = options_.out_dir;
  figure_options.formats = options_.formats;
  figure_options.show = options_.show;
  const FigureFiles files = write_figure(fig, figure_options);
  for (const auto& file : files.files) summary_["figures"][fig.name].push_back(file.string());
  if (!files.notes.empty()) ProgressTask::clear_line();
  for (const auto& note : files.notes) std::cerr << chapter_ << ": " << note << "\n";
}

void ChapterApp::add_divergence_flag() {
  app_->add_flag("--fail-on-divergence", options_.fail_on_divergence,
                 "exit with code 3 when a simulation diverged (it is reported either way)");
}

void ChapterApp::add_viewer_flag() {
  app_->add_flag("--no-viewer", options_.no_viewer,
                 "write no 3D page (NAME.html, played in a browser) beside the frames");
}

void ChapterApp::add_quick_flag(const std::string& sizes) {
  app_->add_flag(
      "--quick", options_.quick,
      fmt::format("the lecture's experiments at reduced sizes ({}): a first look in a fraction of the "
                  "time; the README's numbers are those of the full run",
                  sizes));
  record_parameters_.push_back([this] { summary_["parameters"]["quick"] = options_.quick; });
}

void ChapterApp::diverged(const std::string& run, const std::string& what) {
  summary_["divergences"].push_back({{"run", run}, {"what", what}});
}

void ChapterApp::parse_only_for_fuzzing() { parse_only = true; }

int ChapterApp::run(int argc, const char* const* argv, const std::function<void()>& body) {
  try {
    app_->parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app_->exit(e);  // --help
    std::cerr << chapter_ << ": error: " << e.what() << "\nRun '" << chapter_
              << " --help' to see every flag, its unit and its allowed range.\n";
    return exit_code::usage;
  }
  if (flag_table_requested_) {
    std::cout << flag_table_.dump(2) << "\n";
    return exit_code::ok;
  }
  for (const auto& record : record_parameters_) record();
  if (parse_only) return exit_code::ok;
  report_ = Report(text(), summary_);
  try {
    if (!options_.no_plot) check_output_folder(options_.out_dir);  // before any computation
    if (!options_.summary_file.empty()) check_summary_file(options_.summary_file);
    body();
    if (!options_.summary_file.empty()) write_file_atomic(options_.summary_file, summary_.dump(2) + "\n");
  } catch (const UsageError& e) {
    std::cerr << chapter_ << ": error: " << e.what() << "\n";
    return exit_code::usage;
  } catch (const std::exception& e) {
    std::cerr << chapter_ << ": failed: " << e.what() << "\n";
    return exit_code::failure;
  }
  if (options_.json) {
    std::cout << summary_.dump(2) << "\n";
  } else if (!options_.quiet && !options_.no_plot && summary_.contains("figures")) {
    std::cout << "\nFigures (data, gnuplot script, renders) are in " << options_.out_dir << "\n";
  }
  const bool any_divergence = summary_.contains("divergences");
  return (any_divergence && options_.fail_on_divergence) ? exit_code::diverged : exit_code::ok;
}

}  // namespace kit
