// Whether --show can open a window here (figure.hpp): a display, and a gnuplot with a window
// terminal.
#include <kit/app/figure.hpp>

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace kit {
namespace {

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

}  // namespace

std::optional<std::string> window_unavailable() {
  if (!has_display()) return "no display (DISPLAY is unset)";
  if (!gnuplot_has_window_terminal())
    return "this gnuplot has no window terminal (gnuplot-nox); install gnuplot-qt to see windows";
  return std::nullopt;
}

}  // namespace kit
