#include <kit/cloth/cloth_scene.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include <kit/base/usage.hpp>

namespace kit {
namespace {
/// The column (or row) a pin coordinate names on an axis of `count` nodes: −1 is the last.
long resolve(int coordinate, int count) { return coordinate < 0 ? long(count) + coordinate : coordinate; }
}  // namespace

namespace {
// The scene on an nx × ny grid, its pins checked against it.
ClothScene on_grid(const ClothScene& scene, int nx, int ny, int n) {
  ClothScene out = scene;
  out.grid.nx = nx, out.grid.ny = ny;
  for (const Pin& pin : scene.pins) {
    const long i = resolve(pin.i, nx), j = resolve(pin.j, ny);
    if (i < 0 || i >= nx || j < 0 || j >= ny)
      throw UsageError(
          fmt::format("resolution {}: pin [{}, {}] lies outside the {} × {} grid", n, pin.i, pin.j, nx, ny));
  }
  return out;
}
}  // namespace

ClothScene at_resolution(const ClothScene& scene, int n) {
  if (n < 2) throw UsageError(fmt::format("resolution {}: a sheet needs at least 2 nodes across", n));
  const ClothGrid& g = scene.grid;
  // Square cells: dy = height/(ny − 1) as close as possible to dx = width/(nx − 1).
  const double rows = std::round(g.height / g.width * (n - 1));
  constexpr double most_rows = INT_MAX / 2;  // keeps ny·nx arithmetic (in long) and int indices safe
  if (!(rows <= most_rows))
    throw UsageError(fmt::format("resolution {}: a {} m × {} m sheet would need {} rows of nodes", n, g.width,
                                 g.height, rows + 1));
  return on_grid(scene, n, std::max(2, int(rows) + 1), n);
}

ClothScene at_longest_side(const ClothScene& scene, int n) {
  if (n < 2) throw UsageError(fmt::format("resolution {}: a sheet needs at least 2 nodes across", n));
  const ClothGrid& g = scene.grid;
  const double other = std::round(std::min(g.width, g.height) / std::max(g.width, g.height) * (n - 1));
  const int short_side = std::max(2, int(other) + 1);
  return g.width >= g.height ? on_grid(scene, n, short_side, n) : on_grid(scene, short_side, n, n);
}

long pinned_node(const ClothGrid& grid, const Pin& pin) {
  const long i = resolve(pin.i, grid.nx), j = resolve(pin.j, grid.ny);
  if (i < 0 || i >= grid.nx || j < 0 || j >= grid.ny)
    throw std::out_of_range(
        fmt::format("pin [{}, {}] outside the {} × {} grid", pin.i, pin.j, grid.nx, grid.ny));
  return grid.index(int(i), int(j));
}

}  // namespace kit
