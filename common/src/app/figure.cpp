// What a figure holds (figure.hpp), and which of a series' points its data file keeps.
#include <kit/app/figure.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace kit {

Series& Panel::add(Series s) {
  if (s.x.size() != s.y.size())
    throw std::invalid_argument(
        fmt::format("series '{}' has {} x and {} y values", s.title, s.x.size(), s.y.size()));
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
    std::array<std::size_t, 4> extremes{first, first, first,
                                        first};  // lowest y, highest y, lowest x, highest x
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
    if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && (!logx || on_log_axis(s.x[i])) &&
        (!logy || on_log_axis(s.y[i])))
      return true;
  return false;
}

}  // namespace kit
