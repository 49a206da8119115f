#pragma once
// Ex 6.2: the spring network of a cloth grid (lecture, "Structural / Shearing / Bending springs";
// Provot 1995). Node (i, j) is joined to
//   structural: (i+1, j) and (i, j+1)                    — the 4 direct neighbours, each pair once;
//   shear:      (i+1, j+1) and (i+1, j−1)                — the 4 diagonal neighbours;
//   bend:       (i+2, j) and (i, j+2)                    — two steps along the axes (Provot's 4),
//               and with BendLayout::eight also (i+2, j+2) and (i+2, j−2)  (ERRATA item 12).
// Each family exists only when the layout asks for it; each spring rests at the distance between
// its nodes at rest.
#include <kit/base/not_implemented.hpp>
#include <kit/cloth/cloth.hpp>

namespace kit {

/// Every spring the layout asks for on the grid, each unordered pair once, with its family's
/// stiffness and damping and its rest length |rest_position(a) − rest_position(b)| [m].
/// Use grid.index(i, j) for node numbers and springs.add(a, b, rest, family, kind).
inline Springs build_springs(const ClothGrid& grid, const SpringLayout& layout) {
  Springs springs;
  // BEGIN SOLUTION ex 6.2: for each family present, for each node, join it to the neighbours ahead of it (offsets +i, and ±j for diagonals) that lie on the grid
  springs.reserve(std::size_t(spring_count(grid.nx, grid.ny, layout)));
  const auto join = [&](const SpringFamily& family, SpringKind kind, int di, int dj) {
    for (int j = 0; j < grid.ny; ++j)
      for (int i = 0; i < grid.nx; ++i) {
        const int i2 = i + di, j2 = j + dj;
        if (i2 < 0 || i2 >= grid.nx || j2 < 0 || j2 >= grid.ny) continue;
        const double rest = (grid.rest_position(i, j) - grid.rest_position(i2, j2)).norm();
        springs.add(grid.index(i, j), grid.index(i2, j2), rest, family, kind);
      }
  };
  if (layout.structural) {
    join(*layout.structural, SpringKind::structural, 1, 0);
    join(*layout.structural, SpringKind::structural, 0, 1);
  }
  if (layout.shear) {
    join(*layout.shear, SpringKind::shear, 1, 1);
    join(*layout.shear, SpringKind::shear, 1, -1);
  }
  if (layout.bend) {
    join(*layout.bend, SpringKind::bend, 2, 0), join(*layout.bend, SpringKind::bend, 0, 2);
    if (layout.bend_layout == BendLayout::eight)
      join(*layout.bend, SpringKind::bend, 2, 2), join(*layout.bend, SpringKind::bend, 2, -2);
  }
  // END SOLUTION
  return springs;
}

}  // namespace kit
