#include <kit/app/figure.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <gnuplot-iostream.h>

#include <kit/app/pdf_creation_date.hpp>
#include <kit/base/atomic_file.hpp>

namespace kit {

Series& Panel::add(Series s) {
  if (s.x.size() != s.y.size())
    throw std::invalid_argument(fmt::format("series '{}' has {} x and {} y values", s.title,
                                            s.x.size(), s.y.size()));
  series.push_back(std::move(s));
  return series.back();
}

Series& Panel::line(std::string title, std::vector<double> x, std::vector<double> y, std::string style) {
  return add({std::move(title), std::move(x), std::move(y), "lines", std::move(style)});
}

Series& Panel::points(std::string title, std::vector<double> x, std::vector<double> y, std::string style) {
  return add({std::move(title), std::move(x), std::move(y), "points", std::move(style)});
}

Panel& Figure::panel(std::string xlabel, std::string ylabel, std::string panel_title) {
  Panel p;
  p.xlabel = std::move(xlabel);
  p.ylabel = std::move(ylabel);
  p.title = std::move(panel_title);
  panels.push_back(std::move(p));
  return panels.back();
}

std::vector<std::size_t> plotted_indices(const Series& s) {
  std::vector<std::size_t> kept;
  const std::size_t n = s.x.size();
  if (n <= max_plotted_points) {
    for (std::size_t i = 0; i < n; ++i) kept.push_back(i);
    return kept;
  }
  // Slices of consecutive points; each keeps its extreme points in y and in x (a phase portrait
  // is a curve in both), in their order, so the envelope of an oscillation or a spike survives.
  // Extremes start from the slice's first finite point: a NaN compares false with everything.
  const std::size_t slices = max_plotted_points / 4;
  for (std::size_t k = 0; k < slices; ++k) {
    const std::size_t begin = k * n / slices, end = (k + 1) * n / slices;
    std::size_t first = begin;
    while (first < end && !(std::isfinite(s.x[first]) && std::isfinite(s.y[first]))) ++first;
    if (first == end) {
      kept.push_back(begin);  // an undefined stretch stays a gap
      continue;
    }
    std::array<std::size_t, 4> extremes{first, first, first, first};  // lowest y, highest y, lowest x, highest x
    for (std::size_t i = first; i < end; ++i) {
      if (s.y[i] < s.y[extremes[0]]) extremes[0] = i;
      if (s.y[i] > s.y[extremes[1]]) extremes[1] = i;
      if (s.x[i] < s.x[extremes[2]]) extremes[2] = i;
      if (s.x[i] > s.x[extremes[3]]) extremes[3] = i;
    }
    std::sort(extremes.begin(), extremes.end());
    for (std::size_t j = 0; j < extremes.size(); ++j)
      if (j == 0 || extremes[j] != extremes[j - 1]) kept.push_back(extremes[j]);
  }
  if (kept.back() != n - 1) kept.push_back(n - 1);
  return kept;
}

bool drawable(const Series& s, bool logx, bool logy) {
  const auto on_log_axis = [](double v) { return v >= log_axis_min && v <= log_axis_max; };
  for (std::size_t i = 0; i < s.x.size(); ++i)
    if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && (!logx || on_log_axis(s.x[i])) && (!logy || on_log_axis(s.y[i])))
      return true;
  return false;
}

namespace {

// `text` as comment lines ("# …" each): a title's line break must not end the comment, or the
// rest of the title becomes a gnuplot command (or data).
std::string comment_line(const std::string& text) {
  std::string out = "# ";
  for (char c : text) out += c == '\n' ? std::string("\n# ") : std::string(1, c);
  return out + "\n";
}

// A POSIX shell single-quoted word: nothing inside is expanded ($(...), backticks, $VAR).
std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// `text` on two lines when it is longer than `width` characters: broken at the ", ", ": " or
// " (" nearest its middle, else at the space nearest it. A long axis label otherwise runs off a short panel, and a long title
// off a narrow figure, once the figure is drawn at the size of its slide.
std::string wrapped(const std::string& text, std::size_t width) {
  std::size_t characters = 0;  // UTF-8: count the bytes that start a character
  for (unsigned char c : text) characters += (c & 0xC0) != 0x80;
  if (characters <= width) return text;
  std::size_t best = std::string::npos;
  const std::size_t middle = text.size() / 2;
  for (const char* separator : {", ", ": ", " ("}) {
    for (auto at = text.find(separator); at != std::string::npos; at = text.find(separator, at + 1)) {
      const std::size_t cut = separator[0] == ' ' ? at : at + 1;  // keep "(" on the second line
      const auto distance = [middle](std::size_t i) { return i > middle ? i - middle : middle - i; };
      if (best == std::string::npos || distance(cut) < distance(best)) best = cut;
    }
  }
  for (auto at = text.find(' '); best == std::string::npos && at != std::string::npos;) {
    std::size_t nearest = at;  // the first space; then the one nearest the middle
    for (; at != std::string::npos; at = text.find(' ', at + 1))
      if ((at > middle ? at - middle : middle - at) < (nearest > middle ? nearest - middle : middle - nearest))
        nearest = at;
    best = nearest;
  }
  if (best == std::string::npos) return text;
  std::string head = text.substr(0, best), tail = text.substr(best);
  while (!tail.empty() && tail.front() == ' ') tail.erase(0, 1);
  return head + "\n" + tail;
}

// A value gnuplot reads: NaN and ±Inf are written as NaN (an undefined point, not drawn).
std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.17g}", v) : std::string("NaN"); }

std::string data_text(const Figure& figure) {
  std::ostringstream out;
  out << comment_line(figure.title) << "# One block per series (gnuplot 'index'); columns: x y\n"
      << "# Series longer than " << max_plotted_points << " points keep the extremes of each of "
      << max_plotted_points / 2 << " slices (what a figure can show); NaN marks an undefined value.\n";
  int index = 0;
  for (const auto& panel : figure.panels) {
    for (const auto& s : panel.series) {
      out << "\n\n# index " << index++ << ": " << (s.title.empty() ? "(no legend entry)" : s.title)
          << "  [" << panel.xlabel << " | " << panel.ylabel << "]\n";
      for (std::size_t i : plotted_indices(s)) out << number(s.x[i]) << ' ' << number(s.y[i]) << '\n';
      if (s.x.empty()) out << "NaN NaN\n";  // an empty block would shift every later index
    }
  }
  return out.str();
}

bool has_display() {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (display && *display) || (wayland && *wayland);
}

// gnuplot-nox has no window terminal; ask gnuplot which terminals it has.
bool gnuplot_has_window_terminal() {
  FILE* pipe = popen("gnuplot -e 'print GPVAL_TERMINALS' 2>&1", "r");
  if (!pipe) return false;
  std::string terminals;
  char buffer[512];
  while (fgets(buffer, sizeof buffer, pipe)) terminals += buffer;
  pclose(pipe);
  std::istringstream words(terminals);
  for (std::string word; words >> word;)
    if (word == "qt" || word == "wxt" || word == "x11") return true;
  return false;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string gnuplot_script(const Figure& figure, const std::string& data_file) {
  std::ostringstream gp;
  gp << comment_line(figure.title)
     << "# Draws " << figure.name << " from " << data_file << ". Restyle freely, then redraw from this folder:\n"
     << "#   gnuplot -e \"fmt='pdf'\" " << figure.name << ".gp     (fmt: pdf, png, svg; or 'show' for a window)\n"
     << "if (!exists(\"fmt\")) fmt = \"png\"\n"
     << "if (!exists(\"out\")) out = \"" << figure.name << ".\" . fmt\n"
     << "# The PDF's size [in] and text size [pt]: a slide build sets them to the slot its deck gives\n"
     << "# the figure (tools/build_slides.sh), so the slide shows the text at font_pt, not scaled down.\n"
     << "if (!exists(\"width_in\")) width_in = " << figure.width_in << "\n"
     << "if (!exists(\"height_in\")) height_in = " << figure.height_in << "\n"
     << "if (!exists(\"font_pt\")) font_pt = 11\n"
     << "if (fmt eq \"pdf\") { eval sprintf(\"set terminal pdfcairo enhanced color size %gin,%gin "
        "font 'Sans,%g' linewidth 1.5\", width_in, height_in, font_pt) }\n"
     << fmt::format("if (fmt eq \"png\") {{ set terminal pngcairo enhanced color size {},{} font \"Sans,10\" linewidth 1.5 }}\n",
                    static_cast<int>(figure.width_in * 150), static_cast<int>(figure.height_in * 150))
     << fmt::format("if (fmt eq \"svg\") {{ set terminal svg enhanced size {},{} font \"Sans,10\" linewidth 1.5 background \"white\" }}\n",
                    static_cast<int>(figure.width_in * 110), static_cast<int>(figure.height_in * 110))
     << "if (fmt ne \"show\") { set output out }\n"
     << "set encoding utf8\n"
     << "data = " << gnuplot_string(data_file) << "\n";
  const bool multi = figure.panels.size() > 1;
  if (multi) gp << "set multiplot title " << gnuplot_string(wrapped(figure.title, 80)) << " font sprintf(\",%g\", font_pt)\n";
  int index = 0;
  const int columns = std::max(1, figure.columns);
  const int rows = static_cast<int>((figure.panels.size() + static_cast<std::size_t>(columns) - 1) / static_cast<std::size_t>(columns));
  const double cell_height = 0.92 / rows, cell_width = 1.0 / columns;
  for (std::size_t p = 0; p < figure.panels.size(); ++p) {
    const Panel& panel = figure.panels[p];
    gp << "\n# --- panel " << p + 1 << (panel.title.empty() ? "" : ": " + panel.title) << "\n";
    if (p) gp << "reset\n";
    if (multi) {
      const int row = static_cast<int>(p) / columns, column = static_cast<int>(p) % columns;
      const auto place = panel.place.value_or(std::array<double, 4>{
          cell_width * column, 0.92 - cell_height * (row + 1), cell_width, cell_height});
      gp << fmt::format("set origin {},{}\nset size {},{}\n", place[0], place[1], place[2], place[3]);
    }
    const std::string title = multi ? panel.title : (panel.title.empty() ? figure.title : figure.title + "\n" + panel.title);
    gp << "set title " << gnuplot_string(wrapped(title, 72)) << "\n"
       << "set xlabel " << gnuplot_string(wrapped(panel.xlabel, 80)) << "\n"
       << "set ylabel " << gnuplot_string(wrapped(panel.ylabel, rows > 1 ? 24 : 34)) << "\n"
       << "set grid lc rgb '#dddddd'\n"
       << "set key " << panel.key << " box opaque samplen 2 spacing 1.2\n";  // room for sub- and superscripts
    if (figure.left_edge) gp << fmt::format("set lmargin at screen {}\n", *figure.left_edge);
    if (figure.right_edge) gp << fmt::format("set rmargin at screen {}\n", *figure.right_edge);
    if (panel.logx) gp << "set logscale x\nset format x \"10^{%L}\"\n";
    if (panel.logy) gp << "set logscale y\nset format y \"10^{%L}\"\n";
    for (const auto& command : panel.commands) gp << command << "\n";
    // A series with no point to draw (all undefined, or none positive on a log axis) is left
    // out of the plot and named in a label, since gnuplot refuses a plot with nothing defined.
    // On a log axis gnuplot cannot span the whole double range (its autoscaled ends underflow
    // to 0 near 1e-308), so values outside [1e-280, 1e280] are left undefined there.
    const std::string x = panel.logx ? "(($1>=1e-280&&$1<=1e280)?$1:NaN)" : "1";
    const std::string y = panel.logy ? "(($2>=1e-280&&$2<=1e280)?$2:NaN)" : "2";
    std::vector<std::string> clauses, empty;
    for (const Series& series : panel.series) {
      const int block = index++;
      if (!drawable(series, panel.logx, panel.logy)) {
        // An empty series has nothing to hide; one whose points cannot be drawn is named.
        if (!series.title.empty() && !series.x.empty()) empty.push_back(series.title);
        continue;
      }
      clauses.push_back(fmt::format("data index {} using {}:{} with {}{} {}", block, x, y, series.with,
                                    series.style.empty() ? "" : " " + series.style,
                                    series.title.empty() ? "notitle" : "title " + gnuplot_string(series.title)));
    }
    if (!empty.empty()) {
      std::string names;
      for (const auto& name : empty) names += (names.empty() ? "" : ", ") + name;
      gp << "set label " << gnuplot_string("nothing to draw" + std::string(panel.logy || panel.logx ? " on a log scale" : "") +
                                   ": " + names) << " at graph 0.02, graph 0.04 left front font \",9\"\n";
    }
    if (clauses.empty()) {  // nothing at all: the axes, the label, and an invisible line
      gp << "unset logscale\nset xrange [0:1]\nset yrange [0:1]\nplot -1 notitle\n";
    } else {
      gp << "plot ";
      for (std::size_t c = 0; c < clauses.size(); ++c) gp << (c ? ", \\\n     " : "") << clauses[c];
      gp << "\n";
    }
  }
  if (multi) gp << "unset multiplot\n";
  return gp.str();
}

std::string gnuplot_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    if (c == '"' || c == '\\' || c == '`') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::optional<std::string> window_unavailable() {
  if (!has_display()) return "no display (DISPLAY is unset)";
  if (!gnuplot_has_window_terminal()) return "this gnuplot has no window terminal (gnuplot-nox); install gnuplot-qt to see windows";
  return std::nullopt;
}

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
  write_file_atomic(dir / data_file, data_text(figure));
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
        gp << "fmt = " << gnuplot_string(format) << "; out = "
           << gnuplot_string((scratch.path().filename() / temporary.filename()).string()) << "\n"
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
      if (!messages.empty()) result.notes.push_back(fmt::format("gnuplot on {}: {}", final_path.filename().string(), messages));
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
