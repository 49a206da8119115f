#include <cstdlib>
#include <fstream>
#include <sstream>

#include <catch2/catch.hpp>

#include <kit/figure.hpp>

#include "process.hpp"

namespace {
std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

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
  CHECK_THAT(slurp(dir.path() / "precise.dat"), Catch::Contains("0.33333333333333331"));
  CHECK(kit::test::files_under(dir.path()).size() == 2);
}

TEST_CASE("the script carries the titles, axis labels, legend and log scales") {
  const auto script = kit::gnuplot_script(sample_figure(), "sample.dat");
  CHECK_THAT(script, Catch::Contains("set multiplot title \"A sample figure\""));
  CHECK_THAT(script, Catch::Contains("set xlabel \"time t [s]\""));
  CHECK_THAT(script, Catch::Contains("set ylabel \"error [m]\""));
  CHECK_THAT(script, Catch::Contains("title \"exact\""));
  CHECK_THAT(script, Catch::Contains("data index 1 using 1:2 with points notitle"));
  CHECK_THAT(script, Catch::Contains("index 2 using 1:2 with points title \"measured\""));
  CHECK_THAT(script, Catch::Contains("set logscale y"));
}

TEST_CASE("a slide author can redraw a figure from its folder with plain gnuplot") {
  kit::test::TempDir dir("figure-redraw");
  kit::FigureOptions options;
  options.dir = dir.path();
  options.formats = {"png"};
  kit::write_figure(sample_figure(), options);
  std::filesystem::remove(dir.path() / "sample.png");
  const std::string command = "cd " + kit::test::shell_quote(dir.path().string()) +
                              " && gnuplot -e \"fmt='svg'\" sample.gp 2>&1";
  REQUIRE(std::system(command.c_str()) == 0);
  CHECK_THAT(slurp(dir.path() / "sample.svg"), Catch::Contains("<svg"));
}

TEST_CASE("an unknown format is refused before anything is written") {
  kit::test::TempDir dir("figure-bad");
  kit::FigureOptions options;
  options.dir = dir.path() / "never";
  options.formats = {"gif"};
  CHECK_THROWS_WITH(kit::write_figure(sample_figure(), options), Catch::Contains("gif"));
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
  CHECK_THAT(files.notes[0], Catch::Contains("no display"));
  CHECK(std::filesystem::exists(dir.path() / "sample.png"));
}
