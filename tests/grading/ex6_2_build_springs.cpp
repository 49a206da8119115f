// ex 6.2: the spring network of a cloth grid (cloth_springs.hpp).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "cloth_springs.hpp"

namespace {
using Pair = std::pair<long, long>;
// The neighbours of every node, worked out here from the grid coordinates, each pair once.
std::map<Pair, kit::SpringKind> expected_pairs(int nx, int ny, const kit::SpringLayout& layout) {
  std::map<Pair, kit::SpringKind> pairs;
  const auto join = [&](bool present, kit::SpringKind kind,
                        std::initializer_list<std::pair<int, int>> offsets) {
    if (!present) return;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (auto [di, dj] : offsets) {
          const int column = i + di, row = j + dj;
          if (column < 0 || column >= nx || row < 0 || row >= ny) continue;
          const long a = long(j) * nx + i, b = long(row) * nx + column;
          pairs[{std::min(a, b), std::max(a, b)}] = kind;
        }
  };
  join(bool(layout.structural), kit::SpringKind::structural, {{1, 0}, {-1, 0}, {0, 1}, {0, -1}});
  join(bool(layout.shear), kit::SpringKind::shear, {{1, 1}, {-1, -1}, {1, -1}, {-1, 1}});
  join(bool(layout.bend), kit::SpringKind::bend, {{2, 0}, {-2, 0}, {0, 2}, {0, -2}});
  join(layout.bend && layout.bend_layout == kit::BendLayout::eight, kit::SpringKind::bend,
       {{2, 2}, {-2, -2}, {2, -2}, {-2, 2}});
  return pairs;
}
}  // namespace

TEST_CASE("ex 6.2: every family asked for, each neighbour pair exactly once, nothing else",
          "[grade][06-cloth-explicit][ex6.2]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 64; ++trial) {
    kit::ClothGrid grid;
    grid.nx = int(kit::test::uniform(rng, 2, 13)), grid.ny = int(kit::test::uniform(rng, 2, 13));
    kit::SpringLayout layout;
    if (trial & 1) layout.structural = kit::SpringFamily{100, 1};
    if (trial & 2) layout.shear = kit::SpringFamily{50, 0.5};
    if (trial & 4) layout.bend = kit::SpringFamily{10, 0.1};
    layout.bend_layout = trial & 8 ? kit::BendLayout::eight : kit::BendLayout::four;
    INFO(grid.nx << "×" << grid.ny << " nodes, layout " << (trial & 15));
    const kit::Springs springs = kit::build_springs(grid, layout);
    const auto expected = expected_pairs(grid.nx, grid.ny, layout);
    REQUIRE(springs.size() == expected.size());
    REQUIRE(springs.a.size() == springs.size());
    REQUIRE(springs.rest.size() == springs.size());
    std::set<Pair> seen;
    for (std::size_t s = 0; s < springs.size(); ++s) {
      const long a = springs.a[s], b = springs.b[s];
      const Pair pair{std::min(a, b), std::max(a, b)};
      CHECK(seen.insert(pair).second);  // no pair twice
      const auto found = expected.find(pair);
      REQUIRE(found != expected.end());
      CHECK(springs.kind[s] == found->second);
    }
  }
}

TEST_CASE("ex 6.2: rest lengths are the distances at rest, on cells that are not square",
          "[grade][06-cloth-explicit][ex6.2]") {
  kit::ClothGrid grid;
  grid.nx = 5, grid.ny = 4, grid.width = 2.0, grid.height = 0.6;  // dx = 0.5, dy = 0.2
  kit::SpringLayout layout;
  layout.structural = kit::SpringFamily{100, 1}, layout.shear = kit::SpringFamily{50, 0.5};
  layout.bend = kit::SpringFamily{10, 0.1}, layout.bend_layout = kit::BendLayout::eight;
  const kit::Springs springs = kit::build_springs(grid, layout);
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const long a = springs.a[s], b = springs.b[s];
    const double di = double(a % 5 - b % 5) * 0.5, dj = double(a / 5 - b / 5) * 0.2;
    CHECK(springs.rest[s] == Approx(std::hypot(di, dj)).epsilon(1e-12));
    const auto& family = *layout.family(springs.kind[s]);
    CHECK(springs.stiffness[s] == family.stiffness);
    CHECK(springs.damping[s] == family.damping);
  }
}

TEST_CASE("ex 6.2: a layout with no family builds no spring", "[grade][06-cloth-explicit][ex6.2]") {
  kit::ClothGrid grid;
  grid.nx = 6, grid.ny = 6;
  CHECK(kit::build_springs(grid, kit::SpringLayout{}).size() == 0);
}
