#include <kit/fem/fem_mesh.hpp>

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include <kit/base/random.hpp>

namespace kit {
namespace {

void require_rectangle(double width, double height, int nx, int ny) {
  if (!(width > 0 && height > 0 && std::isfinite(width) && std::isfinite(height)) || nx < 1 || ny < 1)
    throw std::invalid_argument(
        fmt::format("a {} × {} m rectangle of {} × {} cells: sizes must be positive and "
                    "finite, cell counts at least 1",
                    width, height, nx, ny));
}

// The grid's nodes, row by row from (0, 0).
std::vector<Eigen::Vector2d> grid_nodes(double width, double height, int nx, int ny) {
  std::vector<Eigen::Vector2d> nodes;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) nodes.emplace_back(width * i / nx, height * j / ny);
  return nodes;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();  // twice the signed area of abc
}

// > 0 when d lies inside the circumcircle of the counter-clockwise triangle abc (the classic
// incircle determinant, lifted to the paraboloid).
double incircle(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                const Eigen::Vector2d& d) {
  const Eigen::Vector2d p = a - d, q = b - d, r = c - d;
  return p.squaredNorm() * (q.x() * r.y() - q.y() * r.x()) -
         q.squaredNorm() * (p.x() * r.y() - p.y() * r.x()) +
         r.squaredNorm() * (p.x() * q.y() - p.y() * q.x());
}

// Lawson's flips: an interior edge whose opposite corner lies inside the other triangle's
// circumcircle is replaced by the other diagonal of their (then convex) quadrilateral, until none
// is left. From any valid triangulation this ends at a Delaunay one (Lawson 1977).
void make_delaunay(TriangleMesh& mesh, double scale) {
  const double tolerance = 1e-12 * scale * scale * scale * scale;  // incircle is quartic in lengths
  for (bool flipped = true; flipped;) {
    flipped = false;
    std::map<std::pair<int, int>, std::pair<int, int>> edges;  // directed edge → (triangle, corner)
    for (int t = 0; t < int(mesh.triangles.size()); ++t)
      for (int k = 0; k < 3; ++k)
        edges[{mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3]}] = {t, (k + 2) % 3};
    std::vector<bool> touched(mesh.triangles.size(), false);
    for (const auto& [edge, first] : edges) {
      const auto other = edges.find({edge.second, edge.first});
      if (other == edges.end() || edge.first > edge.second) continue;  // a boundary edge, or seen
      const auto [t, k] = first;
      const auto [u, m] = other->second;
      if (touched[t] || touched[u]) continue;  // changed in this pass: its neighbours next pass
      const int a = edge.first, b = edge.second, c = mesh.triangles[t][k], d = mesh.triangles[u][m];
      const auto& x = mesh.nodes;
      if (incircle(x[a], x[b], x[c], x[d]) <= tolerance) continue;
      if (cross(x[a], x[d], x[c]) <= 0 || cross(x[d], x[b], x[c]) <= 0) continue;  // not convex
      mesh.triangles[t] = {a, d, c};
      mesh.triangles[u] = {d, b, c};
      touched[t] = touched[u] = flipped = true;
    }
  }
}

}  // namespace

TriangleMesh regular_rectangle_mesh(double width, double height, int nx, int ny, CellDiagonal diagonal) {
  require_rectangle(width, height, nx, ny);
  TriangleMesh mesh{grid_nodes(width, height, nx, ny), {}};
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i, b = a + 1, c = a + nx + 2, d = a + nx + 1;  // counter-clockwise
      const bool rising =
          diagonal == CellDiagonal::rising || (diagonal == CellDiagonal::alternating && (i + j) % 2 == 0);
      if (rising) {
        mesh.triangles.push_back({a, b, c});
        mesh.triangles.push_back({a, c, d});
      } else {
        mesh.triangles.push_back({a, b, d});
        mesh.triangles.push_back({b, c, d});
      }
    }
  return mesh;
}

TriangleMesh irregular_rectangle_mesh(double width, double height, int nx, int ny, std::uint64_t seed,
                                      double jitter) {
  if (!(jitter >= 0 && jitter <= 0.45))
    throw std::invalid_argument(fmt::format("jitter {} of a cell: expected [0, 0.45]", jitter));
  // Each cell split along the diagonal that keeps both triangles counter-clockwise once the nodes
  // have moved (a moved cell may be a non-convex quadrilateral: one of its diagonals always works).
  TriangleMesh mesh = regular_rectangle_mesh(width, height, nx, ny, CellDiagonal::rising);
  Random random(seed);
  const double dx = width / nx, dy = height / ny;
  for (int j = 1; j < ny; ++j)
    for (int i = 1; i < nx; ++i) {
      auto& node = mesh.nodes[std::size_t(j * (nx + 1) + i)];
      node.x() += (2 * random.unit() - 1) * jitter * dx;
      node.y() += (2 * random.unit() - 1) * jitter * dy;
    }
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 2) {
    auto& first = mesh.triangles[t];
    auto& second = mesh.triangles[t + 1];
    const int a = first[0], b = first[1], c = first[2], d = second[2];
    if (cross(mesh.nodes[std::size_t(a)], mesh.nodes[std::size_t(b)], mesh.nodes[std::size_t(c)]) <= 0 ||
        cross(mesh.nodes[std::size_t(a)], mesh.nodes[std::size_t(c)], mesh.nodes[std::size_t(d)]) <= 0) {
      first = {a, b, d};
      second = {b, c, d};
    }
  }
  make_delaunay(mesh, std::max(dx, dy));
  return mesh;
}

double triangle_area(const TriangleMesh& mesh, int t) {
  const auto& [a, b, c] = mesh.triangles[std::size_t(t)];
  return 0.5 * cross(mesh.nodes[std::size_t(a)], mesh.nodes[std::size_t(b)], mesh.nodes[std::size_t(c)]);
}

}  // namespace kit
