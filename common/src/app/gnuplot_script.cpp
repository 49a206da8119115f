// A figure as gnuplot reads it (figure.hpp): its data file and the script that draws it, with
// every text a title or label holds made safe for gnuplot's strings and comments.
#include <kit/app/figure.hpp>

#include <cmath>
#include <sstream>

#include <fmt/format.h>

namespace kit {
namespace {

// `text` as comment lines ("# …" each): a title's line break must not end the comment, or the
// rest of the title becomes a gnuplot command (or data).
std::string comment_line(const std::string& text) {
  std::string out = "# ";
  for (char c : text) out += c == '\n' ? std::string("\n# ") : std::string(1, c);
  return out + "\n";
}

// `text` on two lines when it is longer than `width` characters: broken at the ", ", ": " or
// " (" nearest its middle, else at the space nearest it. A long axis label otherwise runs off a short panel,
// and a long title off a narrow figure, once the figure is drawn at the size of its slide.
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
      if ((at > middle ? at - middle : middle - at) <
          (nearest > middle ? nearest - middle : middle - nearest))
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

}  // namespace

std::string figure_data_text(const Figure& figure) {
  std::ostringstream out;
  out << comment_line(figure.title) << "# One block per series (gnuplot 'index'); columns: x y\n"
      << "# Series longer than " << max_plotted_points << " points keep the extremes of each of "
      << max_plotted_points / 2 << " slices (what a figure can show); NaN marks an undefined value.\n";
  int index = 0;
  for (const auto& panel : figure.panels) {
    for (const auto& s : panel.series) {
      out << "\n\n# index " << index++ << ": " << (s.title.empty() ? "(no legend entry)" : s.title) << "  ["
          << panel.xlabel << " | " << panel.ylabel << "]\n";
      for (std::size_t i : plotted_indices(s)) out << number(s.x[i]) << ' ' << number(s.y[i]) << '\n';
      if (s.x.empty()) out << "NaN NaN\n";  // an empty block would shift every later index
    }
  }
  return out.str();
}

std::string gnuplot_script(const Figure& figure, const std::string& data_file) {
  std::ostringstream gp;
  gp << comment_line(figure.title) << "# Draws " << figure.name << " from " << data_file
     << ". Restyle freely, then redraw from this folder:\n"
     << "#   gnuplot -e \"fmt='pdf'\" " << figure.name
     << ".gp     (fmt: pdf, png, svg; or 'show' for a window)\n"
     << "if (!exists(\"fmt\")) fmt = \"png\"\n"
     << "if (!exists(\"out\")) out = \"" << figure.name << ".\" . fmt\n"
     << "# The PDF's size [in] and text size [pt]: a slide build sets them to the slot its deck gives\n"
     << "# the figure (tools/build_slides.sh), so the slide shows the text at font_pt, not scaled down.\n"
     << "if (!exists(\"width_in\")) width_in = " << figure.width_in << "\n"
     << "if (!exists(\"height_in\")) height_in = " << figure.height_in << "\n"
     << "if (!exists(\"font_pt\")) font_pt = 11\n"
     << "if (fmt eq \"pdf\") { eval sprintf(\"set terminal pdfcairo enhanced color size %gin,%gin "
        "font 'Sans,%g' linewidth 1.5\", width_in, height_in, font_pt) }\n"
     << fmt::format("if (fmt eq \"png\") {{ set terminal pngcairo enhanced color size {},{} font \"Sans,10\" "
                    "linewidth 1.5 }}\n",
                    static_cast<int>(figure.width_in * 150), static_cast<int>(figure.height_in * 150))
     << fmt::format("if (fmt eq \"svg\") {{ set terminal svg enhanced size {},{} font \"Sans,10\" linewidth "
                    "1.5 background \"white\" }}\n",
                    static_cast<int>(figure.width_in * 110), static_cast<int>(figure.height_in * 110))
     << "if (fmt ne \"show\") { set output out }\n"
     << "set encoding utf8\n"
     << "data = " << gnuplot_string(data_file) << "\n";
  const bool multi = figure.panels.size() > 1;
  if (multi)
    gp << "set multiplot title " << gnuplot_string(wrapped(figure.title, 80))
       << " font sprintf(\",%g\", font_pt)\n";
  int index = 0;
  const int columns = std::max(1, figure.columns);
  const int rows = static_cast<int>((figure.panels.size() + static_cast<std::size_t>(columns) - 1) /
                                    static_cast<std::size_t>(columns));
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
    const std::string title =
        multi ? panel.title : (panel.title.empty() ? figure.title : figure.title + "\n" + panel.title);
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
      clauses.push_back(
          fmt::format("data index {} using {}:{} with {}{} {}", block, x, y, series.with,
                      series.style.empty() ? "" : " " + series.style,
                      series.title.empty() ? "notitle" : "title " + gnuplot_string(series.title)));
    }
    if (!empty.empty()) {
      std::string names;
      for (const auto& name : empty) names += (names.empty() ? "" : ", ") + name;
      gp << "set label "
         << gnuplot_string("nothing to draw" +
                           std::string(panel.logy || panel.logx ? " on a log scale" : "") + ": " + names)
         << " at graph 0.02, graph 0.04 left front font \",9\"\n";
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

}  // namespace kit
