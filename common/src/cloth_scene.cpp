#include <kit/cloth_scene.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include <kit/usage.hpp>

namespace kit {
namespace {
/// The column (or row) a pin coordinate names on an axis of `count` nodes: −1 is the last.
long resolve(int coordinate, int count) { return coordinate < 0 ? long(count) + coordinate : coordinate; }
}  // namespace

ClothScene at_resolution(const ClothScene& scene, int n) {
  if (n < 2) throw UsageError(fmt::format("resolution {}: a sheet needs at least 2 nodes across", n));
  ClothScene out = scene;
  const ClothGrid& g = scene.grid;
  // Square cells: dy = height/(ny − 1) as close as possible to dx = width/(nx − 1).
  const double rows = std::round(g.height / g.width * (n - 1));
  constexpr double most_rows = INT_MAX / 2;  // keeps ny·nx arithmetic (in long) and int indices safe
  if (!(rows <= most_rows))
    throw UsageError(fmt::format("resolution {}: a {} m × {} m sheet would need {} rows of nodes", n, g.width,
                                 g.height, rows + 1));
  out.grid.nx = n;
  out.grid.ny = std::max(2, int(rows) + 1);
  for (const Pin& pin : scene.pins) {
    const long i = resolve(pin.i, n), j = resolve(pin.j, out.grid.ny);
    if (i < 0 || i >= n || j < 0 || j >= out.grid.ny)
      throw UsageError(fmt::format("resolution {}: pin [{}, {}] lies outside the {} × {} grid", n, pin.i,
                                   pin.j, n, out.grid.ny));
  }
  return out;
}

long pinned_node(const ClothGrid& grid, const Pin& pin) {
  const long i = resolve(pin.i, grid.nx), j = resolve(pin.j, grid.ny);
  if (i < 0 || i >= grid.nx || j < 0 || j >= grid.ny)
    throw std::out_of_range(
        fmt::format("pin [{}, {}] outside the {} × {} grid", pin.i, pin.j, grid.nx, grid.ny));
  return grid.index(int(i), int(j));
}

}  // namespace kit
