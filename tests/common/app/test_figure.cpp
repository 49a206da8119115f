#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <kit_catch.hpp>

#include <kit/app/figure.hpp>

#include "process.hpp"

namespace {
using kit::test::slurp;

kit::Figure sample_figure() {
  kit::Figure fig("sample", "A sample figure");
  auto& p = fig.panel("time t [s]", "height x [m]", "top");
  p.line("exact", {0, 1, 2}, {0, 1, 4});
  p.points("", {}, {});  // an empty series must not shift the later blocks
  auto& q = fig.panel("time t [s]", "error [m]", "bottom");
  q.logy = true;
  q.points("measured", {0.5, 1.5}, {1e-3, 1e-6});
  return fig;
}
}  // namespace

TEST_CASE("a figure is written as data, script, PDF and PNG, all complete") {
  kit::test::TempDir dir("figure");
  kit::FigureOptions options;
  options.dir = dir.path() / "nested";
  const auto files = kit::write_figure(sample_figure(), options);
  REQUIRE(files.files.size() == 4);
  CHECK(slurp(options.dir / "sample.png").substr(1, 3) == "PNG");
  CHECK(slurp(options.dir / "sample.pdf").substr(0, 5) == "%PDF-");
  CHECK(slurp(options.dir / "sample.pdf").find("%%EOF") != std::string::npos);
  CHECK(files.notes.empty());
  // No temporary file is left behind.
  CHECK(kit::test::files_under(dir.path()).size() == 4);
}

TEST_CASE("the data file holds one block per series, with full precision") {
  kit::Figure fig("precise", "precision");
  fig.panel("x [1]", "y [1]").line("third", {1.0}, {1.0 / 3.0});
  kit::test::TempDir dir("figure-data");
  kit::FigureOptions options;
  options.dir = dir.path();
  options.render = false;
  kit::write_figure(fig, options);
  CHECK_THAT(slurp(dir.path() / "precise.dat"), ContainsSubstring("0.33333333333333331"));
  CHECK(kit::test::files_under(dir.path()).size() == 2);
}

TEST_CASE("the script carries the titles, axis labels, legend and log scales") {
  const auto script = kit::gnuplot_script(sample_figure(), "sample.dat");
  CHECK_THAT(script, ContainsSubstring("set multiplot title \"A sample figure\""));
  CHECK_THAT(script, ContainsSubstring("set xlabel \"time t [s]\""));
  CHECK_THAT(script, ContainsSubstring("set ylabel \"error [m]\""));
  CHECK_THAT(script, ContainsSubstring("title \"exact\""));
  // The empty series keeps its data block (index 1), so later indices hold, but is not plotted.
  CHECK_THAT(script, !ContainsSubstring("data index 1 "));
  CHECK_THAT(script, ContainsSubstring(
                         "index 2 using 1:(($2>=1e-280&&$2<=1e280)?$2:NaN) with points title \"measured\""));
  CHECK_THAT(script, ContainsSubstring("set logscale y"));
}

TEST_CASE("a slide author can redraw a figure from its folder with plain gnuplot") {
  kit::test::TempDir dir("figure-redraw");
  kit::FigureOptions options;
  options.dir = dir.path();
  options.formats = {"png"};
  kit::write_figure(sample_figure(), options);
  std::filesystem::remove(dir.path() / "sample.png");
  const std::string command =
      "cd " + kit::test::shell_quote(dir.path().string()) + " && gnuplot -e \"fmt='svg'\" sample.gp 2>&1";
  REQUIRE(std::system(command.c_str()) == 0);
  CHECK_THAT(slurp(dir.path() / "sample.svg"), ContainsSubstring("<svg"));
}

TEST_CASE("an unknown format is refused before anything is written") {
  kit::test::TempDir dir("figure-bad");
  kit::FigureOptions options;
  options.dir = dir.path() / "never";
  options.formats = {"gif"};
  CHECK_THROWS_WITH(kit::write_figure(sample_figure(), options), ContainsSubstring("gif"));
  CHECK_FALSE(std::filesystem::exists(options.dir));
}

TEST_CASE("--show without a display writes the files and says why no window opened") {
  kit::test::TempDir dir("figure-show");
  kit::FigureOptions options;
  options.dir = dir.path();
  options.formats = {"png"};
  options.show = true;
  const char* display = std::getenv("DISPLAY");
  const std::string saved = display ? display : "";
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  const auto files = kit::write_figure(sample_figure(), options);
  if (!saved.empty()) setenv("DISPLAY", saved.c_str(), 1);
  REQUIRE(files.notes.size() == 1);
  CHECK_THAT(files.notes[0], ContainsSubstring("no display"));
  CHECK(std::filesystem::exists(dir.path() / "sample.png"));
}

TEST_CASE("a relative figure folder and one named with shell syntax are written literally, nothing run") {
  kit::test::TempDir dir("figure-paths");
  const auto previous = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  kit::FigureOptions options;
  options.formats = {"png"};
  options.dir = "relative/out";  // relative to the current folder, not to gnuplot's
  CHECK_NOTHROW(kit::write_figure(sample_figure(), options));
  CHECK(std::filesystem::exists(dir.path() / "relative/out/sample.png"));
  options.dir = "$(touch injected) `touch injected2` it's";
  CHECK_NOTHROW(kit::write_figure(sample_figure(), options));
  CHECK(std::filesystem::exists(dir.path() / "$(touch injected) `touch injected2` it's" / "sample.png"));
  CHECK_FALSE(std::filesystem::exists(dir.path() / "injected"));
  CHECK_FALSE(std::filesystem::exists(dir.path() / "relative/out/injected"));
  CHECK_FALSE(std::filesystem::exists(dir.path() / "injected2"));
  std::filesystem::current_path(previous);
}

TEST_CASE("text with backquotes reaches gnuplot as text: no command in a title, label or legend runs") {
  kit::test::TempDir dir("figure-backquotes");
  const auto marker = [&](const char* name) { return (dir.path() / name).string(); };
  // gnuplot runs `command` even inside double quotes: a scene named so would run it.
  kit::Figure fig("scene", std::string("scene `touch ") + marker("title") + "`");
  auto& p = fig.panel(std::string("x `touch ") + marker("xlabel") + "` [m]", "y [m]", "panel");
  p.line(std::string("series `touch ") + marker("legend") + "`", {0, 1}, {0, 1});
  p.commands.push_back("set xtics (" + kit::gnuplot_string(std::string("`touch ") + marker("tic") + "`") +
                       " 0.5)");
  kit::FigureOptions options;
  options.dir = dir.path() / "out";
  options.formats = {"png"};
  REQUIRE_NOTHROW(kit::write_figure(fig, options));
  CHECK(std::filesystem::exists(dir.path() / "out" / "scene.png"));
  for (const char* name : {"title", "xlabel", "legend", "tic"}) {
    INFO(name);
    CHECK_FALSE(std::filesystem::exists(dir.path() / name));
  }
  CHECK(kit::gnuplot_string("a`b\"c\\d\ne") == "\"a\\`b\\\"c\\\\d\\ne\"");
}

TEST_CASE("a log panel with nothing positive to draw still renders, and names what it could not draw") {
  kit::test::TempDir dir("figure-log");
  kit::Figure fig("zeros", "Errors that are exactly zero");
  auto& p = fig.panel("step Δt [s]", "|error| [m]");
  p.logx = p.logy = true;
  p.points("exact to the last bit", {1e-3, 1e-2}, {0.0, 0.0});
  p.points("diverged", {1e-3, 1e-2}, {std::nan(""), INFINITY});
  auto& q = fig.panel("step Δt [s]", "|error| [m]");
  q.logy = true;
  q.points("some positive", {1, 2, 3, 4}, {-1.0, 0.0, 1e-3, 1e-300});  // 1e-300: below what gnuplot can scale
  kit::FigureOptions options;
  options.dir = dir.path();
  options.formats = {"png"};
  kit::FigureFiles files;
  REQUIRE_NOTHROW(files = kit::write_figure(fig, options));
  CHECK(std::filesystem::exists(dir.path() / "zeros.png"));
  const std::string script = slurp(dir.path() / "zeros.gp");
  CHECK(script.find("nothing to draw on a log scale: exact to the last bit, diverged") != std::string::npos);
  CHECK(slurp(dir.path() / "zeros.dat").find("inf") == std::string::npos);  // written as NaN
}

TEST_CASE("a series of a million points is thinned to the extremes of 1000 slices, the spike kept") {
  kit::Series s;
  for (int i = 0; i < 1'000'000; ++i) {
    s.x.push_back(i);
    s.y.push_back(std::sin(i * 1e-3));
  }
  s.y[123'457] = 50.0;  // one spike
  const auto kept = kit::plotted_indices(s);
  CHECK(kept.size() <= kit::max_plotted_points + 1);
  CHECK(kept.size() >= kit::max_plotted_points / 4);
  CHECK(std::find(kept.begin(), kept.end(), 123'457u) != kept.end());
  CHECK(kept.front() <= 1);
  CHECK(kept.back() == 999'999u);
  CHECK(std::is_sorted(kept.begin(), kept.end()));
  kit::Series small{"", {1, 2, 3}, {1, 2, 3}, "lines", ""};
  CHECK(kit::plotted_indices(small).size() == 3);
  // A phase portrait (x = cos, y = sin over many turns) keeps its x extremes too: not a line.
  kit::Series phase;
  for (int i = 0; i < 1'000'000; ++i)
    phase.x.push_back(std::cos(i * 0.01)), phase.y.push_back(std::sin(i * 0.01));
  double lowest_x = 1;
  for (std::size_t i : kit::plotted_indices(phase)) lowest_x = std::min(lowest_x, phase.x[i]);
  CHECK(lowest_x < -0.999);
}

TEST_CASE("a panel stays usable after more panels are added (the figure keeps references valid)") {
  kit::Figure figure("panels", "references");
  auto& first = figure.panel("x [m]", "y [m]");
  for (int i = 0; i < 64; ++i) figure.panel("x [m]", "y [m]");  // would reallocate a vector
  first.line("drawn later", {0.0, 1.0}, {0.0, 1.0});
  REQUIRE(figure.panels.front().series.size() == 1);
  CHECK(figure.panels.front().series.front().title == "drawn later");
}

TEST_CASE("a title on two lines stays a comment in the data and the script, and the figure draws") {
  kit::test::TempDir dir("figure-two-lines");
  kit::Figure fig = sample_figure();
  fig.title = "first line\nsecond line (a command if it left the comment)";
  kit::FigureOptions options;
  options.dir = dir.path();
  options.formats = {"png"};
  REQUIRE_NOTHROW(kit::write_figure(fig, options));
  for (const char* file : {"sample.dat", "sample.gp"}) {
    const std::string text = slurp(dir.path() / file);
    INFO(file);
    CHECK(text.find("\n# second line") != std::string::npos);
    CHECK(text.find("\nsecond line") == std::string::npos);
  }
}
