// The cloth grid and the spring list (cloth.hpp).
#include <algorithm>

#include <kit/cloth/cloth.hpp>

namespace kit {

NodeArray ClothGrid::rest_positions() const {
  NodeArray x(nodes(), 3);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) x.row(index(i, j)) = rest_position(i, j).transpose();
  return x;
}

Eigen::VectorXd ClothGrid::node_masses() const {
  // Each cell's mass ρ·dx·dy goes a quarter to each of its corners: interior nodes get a whole
  // cell's worth, edge nodes half, corners a quarter; the total is ρ·width·height.
  const double quarter = 0.25 * areal_density * dx() * dy();
  Eigen::VectorXd m = Eigen::VectorXd::Zero(nodes());
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i)
      for (long node : {index(i, j), index(i + 1, j), index(i, j + 1), index(i + 1, j + 1)})
        m[node] += quarter;
  return m;
}

void Springs::reserve(std::size_t n) {
  a.reserve(n), b.reserve(n), rest.reserve(n), stiffness.reserve(n), damping.reserve(n), kind.reserve(n);
}

void Springs::add(long node_a, long node_b, double rest_length, const SpringFamily& family, SpringKind k) {
  a.push_back(std::int32_t(node_a));
  b.push_back(std::int32_t(node_b));
  rest.push_back(rest_length);
  stiffness.push_back(family.stiffness);
  damping.push_back(family.damping);
  kind.push_back(k);
}

long Springs::count(SpringKind k) const {
  long n = 0;
  for (SpringKind s : kind) n += s == k;
  return n;
}

long spring_count(int nx, int ny, const SpringLayout& layout) {
  const long x = nx, y = ny;
  // Pairs (i, j)–(i + di, j + dj) that fit on the grid, one spring per unordered pair.
  const auto pairs = [&](long di, long dj) { return std::max(0L, x - di) * std::max(0L, y - dj); };
  long n = 0;
  if (layout.structural) n += pairs(1, 0) + pairs(0, 1);
  if (layout.shear) n += 2 * pairs(1, 1);
  if (layout.bend) {
    n += pairs(2, 0) + pairs(0, 2);
    if (layout.bend_layout == BendLayout::eight) n += 2 * pairs(2, 2);
  }
  return n;
}

}  // namespace kit
