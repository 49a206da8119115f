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
  // TODO(ex 6.2): for each family present, for each node, join it to the neighbours ahead of it (offsets +i, and ±j for diagonals) that lie on the grid
  throw kit::NotImplemented("ex 6.2", "cloth_springs.hpp");
  return springs;
}

}  // namespace kit
