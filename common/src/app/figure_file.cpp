// Writing a figure (figure.hpp): its data file and script, then each format gnuplot draws,
// through temporary names, so that a figure is either complete or absent.
#include <kit/app/figure.hpp>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <gnuplot-iostream.h>

#include <kit/app/pdf_creation_date.hpp>
#include <kit/base/atomic_file.hpp>

namespace kit {
namespace {

// A POSIX shell single-quoted word: nothing inside is expanded ($(...), backticks, $VAR).
std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

FigureFiles write_figure(const Figure& figure, const FigureOptions& options) {
  namespace fs = std::filesystem;
  for (const auto& format : options.formats)
    if (format != "pdf" && format != "png" && format != "svg")
      throw std::invalid_argument(fmt::format("figure format '{}': expected pdf, png or svg", format));
  // Absolute, so that the log and the renders land where asked after gnuplot's `cd`.
  const fs::path dir = fs::absolute(options.dir);
  fs::create_directories(dir);
  FigureFiles result;
  const std::string data_file = figure.name + ".dat";
  write_file_atomic(dir / data_file, figure_data_text(figure));
  write_file_atomic(dir / (figure.name + ".gp"), gnuplot_script(figure, data_file));
  result.files = {dir / data_file, dir / (figure.name + ".gp")};

  if (options.render) {
    // gnuplot writes into a private folder that a signal removes: a gnuplot still running
    // after a SIGTERM to the chapter alone then cannot leave its temporary behind.
    ScratchFolder scratch(dir / figure.name);
    for (const auto& format : options.formats) {
      const fs::path final_path = dir / (figure.name + "." + format);
      const fs::path temporary = scratch.file(figure.name + "." + format);
      const fs::path log = scratch.file(figure.name + "." + format + ".gnuplot-log");
      {
        // gnuplot-iostream: a pipe into a batch gnuplot run from the figure's folder, so the
        // script's relative data path works exactly as it will for a slide author. Its
        // standard output is discarded: were the output file not creatable, gnuplot would
        // draw onto it instead.
        Gnuplot gp(fmt::format("cd {} && gnuplot >/dev/null 2>{}", shell_quoted(dir.string()),
                               shell_quoted(log.string())));
        gp << "fmt = " << gnuplot_string(format)
           << "; out = " << gnuplot_string((scratch.path().filename() / temporary.filename()).string())
           << "\n"
           << "load " << gnuplot_string(figure.name + ".gp") << "\n";
      }  // the destructor waits for gnuplot to finish
      const std::string messages = read_file(log);
      discard_temporary(log);
      if (!fs::exists(temporary) || fs::file_size(temporary) == 0) {
        discard_temporary(temporary);
        throw std::runtime_error(fmt::format("gnuplot could not draw {}: {}", final_path.string(), messages));
      }
      if (format == "pdf") pin_pdf_creation_date(temporary);
      commit_file(temporary, final_path);
      result.files.push_back(final_path);
      if (!messages.empty())
        result.notes.push_back(fmt::format("gnuplot on {}: {}", final_path.filename().string(), messages));
    }
  }
  if (options.show) {
    if (const auto why = window_unavailable()) {
      result.notes.push_back(fmt::format("--show: {}; the figure files are written", *why));
    } else {
      Gnuplot gp(fmt::format("cd {} && gnuplot -persist", shell_quoted(dir.string())));
      gp << "fmt = \"show\"\nload " << gnuplot_string(figure.name + ".gp") << "\n";
    }
  }
  return result;
}

}  // namespace kit
