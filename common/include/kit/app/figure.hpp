#pragma once
// Figures: for each one, the data (name.dat), the gnuplot script that draws it (name.gp,
// restylable without rerunning anything) and its renders (PDF for slides, PNG, SVG on request).
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <kit/app/look.hpp>

namespace kit {

/// One curve or point set, stored as one data block (gnuplot `index`) of name.dat.
struct Series {
  std::string title;           ///< legend entry; empty means no entry. gnuplot's enhanced
                               ///< text applies: x_0 subscript, t^2 superscript, no bare ~
  std::vector<double> x, y;    ///< same length
  std::string with = "lines";  ///< gnuplot style: lines, points, linespoints, impulses…
  std::string style;           ///< extra gnuplot options, e.g. "lw 2 dt 2 lc rgb '#d62728'"
};

/// One set of axes.
struct Panel {
  std::string title;
  std::string xlabel;  ///< quantity and unit, e.g. "time t [s]"
  std::string ylabel;
  bool logx = false;
  bool logy = false;
  /// gnuplot `set key` placement. The default, outside to the right, never hides data; inside
  /// placements ("bottom right") suit panels whose corner is known to be empty.
  std::string key = "outside right";
  std::vector<Series> series;
  std::vector<std::string> commands;  ///< extra gnuplot commands: ranges, labels, arrows
  /// Where the panel sits, as fractions of the canvas (x, y, width, height); unset = stacked.
  std::optional<std::array<double, 4>> place;

  Series& add(Series s);
  Series& line(std::string title, std::vector<double> x, std::vector<double> y, std::string style = "");
  Series& points(std::string title, std::vector<double> x, std::vector<double> y, std::string style = "");
};

/// n + 1 samples (t_i, f(t_i)) of a smooth curve on [t0, t1], t_i evenly spaced, for the exact
/// solutions drawn under the methods' points.
template <class F>
std::pair<std::vector<double>, std::vector<double>> sample(F&& f, double t0, double t1, int n = 200) {
  std::vector<double> t, y;
  for (int i = 0; i <= n; ++i) {
    t.push_back(t0 + (t1 - t0) * i / n);
    y.push_back(f(t.back()));
  }
  return {std::move(t), std::move(y)};
}

struct Figure {
  std::string name;   ///< file stem: name.dat, name.gp, name.pdf, name.png, name.svg
  std::string title;  ///< shown above all panels
  double width_in = 7.0;
  double height_in = 4.5;
  /// Plot-area edges as canvas fractions, the same for every panel so stacked axes line up
  /// (a legend "outside right" goes beyond right_edge). Unset: gnuplot chooses.
  std::optional<double> left_edge, right_edge;
  /// Panels without a `place` fill a grid this many columns wide, row by row.
  int columns = 1;
  std::deque<Panel> panels;  ///< a deque: the reference panel() returns stays valid when more are added

  Figure(std::string name, std::string title) : name(std::move(name)), title(std::move(title)) {}
  Panel& panel(std::string xlabel, std::string ylabel, std::string panel_title = "");
};

struct FigureOptions {
  std::filesystem::path dir;                       ///< created when missing
  std::vector<std::string> formats{"pdf", "png"};  ///< any of pdf, png, svg
  bool render = true;                              ///< false: data and script only
  bool show = false;                               ///< also open an interactive window
};

struct FigureFiles {
  std::vector<std::filesystem::path> files;  ///< everything written, data and script first
  std::vector<std::string> notes;            ///< gnuplot warnings, or why --show did nothing
};

/// Writes name.dat and name.gp into options.dir, then each render, every file through a
/// temporary name. Throws std::runtime_error when gnuplot cannot produce a render.
FigureFiles write_figure(const Figure& figure, const FigureOptions& options);

/// A series longer than this is thinned in the data file to the extremes in x and y of max/4
/// slices: a figure shows a few thousand points, not millions.
inline constexpr std::size_t max_plotted_points = 4000;
/// The indices of `s` written to the data file (all of them, or the thinned extremes).
std::vector<std::size_t> plotted_indices(const Series& s);
/// What a log axis can show: gnuplot's autoscaled ends underflow to 0 near 1e-308.
inline constexpr double log_axis_min = 1e-280, log_axis_max = 1e280;
/// |v| floored at 1e-17, below round-off of any O(1) quantity: an exact zero (no ghost force, an
/// exactly conserved invariant) still shows on a log axis, at the bottom.
inline double magnitude_on_log_axis(double v) { return std::max(std::abs(v), 1e-17); }
/// True when `s` has a point gnuplot can draw: finite, and in [log_axis_min, log_axis_max] on a
/// log axis.
bool drawable(const Series& s, bool logx, bool logy);

/// Why --show cannot open a window here ("no display (DISPLAY is unset)", "this gnuplot has no
/// window terminal …"), or nothing when it can.
std::optional<std::string> window_unavailable();

/// `text` as a gnuplot double-quoted string literal: quotes, backslashes and backquotes escaped,
/// a line break written \n. Backquotes matter: gnuplot runs a backquoted shell command even
/// inside double quotes, and titles carry scene names from files.
std::string gnuplot_string(const std::string& text);

/// The gnuplot script for `figure` reading `data_file` (exposed for tests).
std::string gnuplot_script(const Figure& figure, const std::string& data_file);
/// The data file's text: a comment block, then one block per series (gnuplot's 'index'), x y
/// per line, thinned as plotted_indices says; NaN for an undefined value.
std::string figure_data_text(const Figure& figure);

}  // namespace kit
