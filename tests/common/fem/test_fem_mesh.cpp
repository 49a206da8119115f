// Chapter 9's meshes: the rectangle covered once by counter-clockwise triangles, the irregular
// mesh Delaunay, on the regular mesh's boundary nodes, and the same on every run.
#include <cmath>
#include <map>
#include <utility>

#include <kit_catch.hpp>

#include <kit/fem/fem_mesh.hpp>

namespace {
using kit::TriangleMesh;

// Checks that the mesh covers the width × height rectangle once: every triangle counter-clockwise,
// the areas summing to the rectangle's, every edge inside shared by two triangles (once each way),
// and V − E + F = 1 (a disc).
void check_covers(const TriangleMesh& mesh, double width, double height) {
  double area = 0;
  std::map<std::pair<int, int>, int> directed;
  for (int t = 0; t < int(mesh.triangles.size()); ++t) {
    CHECK(kit::triangle_area(mesh, t) > 0);
    area += kit::triangle_area(mesh, t);
    for (int k = 0; k < 3; ++k)
      ++directed[{mesh.triangles[std::size_t(t)][std::size_t(k)],
                  mesh.triangles[std::size_t(t)][std::size_t((k + 1) % 3)]}];
  }
  CHECK(area == Approx(width * height).epsilon(1e-12));
  long edges = 0;
  for (const auto& [edge, count] : directed) {
    CHECK(count == 1);  // two triangles never run along one edge the same way: no overlap
    if (!directed.count({edge.second, edge.first}) || edge.first < edge.second) ++edges;
  }
  CHECK(long(mesh.nodes.size()) - edges + long(mesh.triangles.size()) == 1);
}

bool on_boundary(const Eigen::Vector2d& p, double width, double height) {
  return p.x() == 0 || p.y() == 0 || p.x() == width || p.y() == height;
}
}  // namespace

TEST_CASE("fem mesh: a regular rectangle mesh, each diagonal choice, covers the rectangle once",
          "[fem][mesh]") {
  for (auto diagonal :
       {kit::CellDiagonal::rising, kit::CellDiagonal::falling, kit::CellDiagonal::alternating}) {
    const TriangleMesh mesh = kit::regular_rectangle_mesh(2.0, 0.5, 8, 3, diagonal);
    CHECK(mesh.nodes.size() == 9 * 4);
    CHECK(mesh.triangles.size() == 2 * 8 * 3);
    check_covers(mesh, 2.0, 0.5);
  }
  // The first cell: rising splits it along (0,0)-(1,1), falling along (1,0)-(0,1).
  const auto rising = kit::regular_rectangle_mesh(1, 1, 1, 1, kit::CellDiagonal::rising);
  const auto falling = kit::regular_rectangle_mesh(1, 1, 1, 1, kit::CellDiagonal::falling);
  CHECK(rising.triangles[0] == std::array<int, 3>{0, 1, 3});
  CHECK(falling.triangles[0] == std::array<int, 3>{0, 1, 2});
  CHECK_THROWS_AS(kit::regular_rectangle_mesh(0, 1, 1, 1, kit::CellDiagonal::rising), std::invalid_argument);
  CHECK_THROWS_AS(kit::regular_rectangle_mesh(1, 1, 0, 1, kit::CellDiagonal::rising), std::invalid_argument);
}

TEST_CASE("fem mesh: the irregular mesh is Delaunay, keeps the boundary nodes, and is the same for a seed",
          "[fem][mesh]") {
  const double width = 2.0, height = 0.5;
  const TriangleMesh regular = kit::regular_rectangle_mesh(width, height, 16, 4, kit::CellDiagonal::rising);
  const TriangleMesh mesh = kit::irregular_rectangle_mesh(width, height, 16, 4, 20261124);
  REQUIRE(mesh.nodes.size() == regular.nodes.size());
  check_covers(mesh, width, height);
  int moved = 0;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    if (on_boundary(regular.nodes[n], width, height)) {
      CHECK(mesh.nodes[n] == regular.nodes[n]);  // the same supports and loads in every mesh
    } else {
      moved += mesh.nodes[n] != regular.nodes[n];
      CHECK(std::abs(mesh.nodes[n].x() - regular.nodes[n].x()) <= 0.3 * width / 16);
      CHECK(std::abs(mesh.nodes[n].y() - regular.nodes[n].y()) <= 0.3 * height / 4);
    }
  }
  CHECK(moved == 15 * 3);
  // Delaunay: no node strictly inside any triangle's circumcircle.
  for (const auto& [a, b, c] : mesh.triangles) {
    const Eigen::Vector2d pa = mesh.nodes[std::size_t(a)], pb = mesh.nodes[std::size_t(b)],
                          pc = mesh.nodes[std::size_t(c)];
    // The circumcentre from the perpendicular bisectors.
    const Eigen::Vector2d ab = pb - pa, ac = pc - pa;
    const double d = 2 * (ab.x() * ac.y() - ab.y() * ac.x());
    const Eigen::Vector2d centre =
        pa + Eigen::Vector2d(ac.y() * ab.squaredNorm() - ab.y() * ac.squaredNorm(),
                             ab.x() * ac.squaredNorm() - ac.x() * ab.squaredNorm()) /
                 d;
    const double radius = (centre - pa).norm();
    for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
      if (int(n) != a && int(n) != b && int(n) != c)
        CHECK((mesh.nodes[n] - centre).norm() >= radius * (1 - 1e-9));
  }
  // The same seed gives the same mesh; another gives another.
  const TriangleMesh again = kit::irregular_rectangle_mesh(width, height, 16, 4, 20261124);
  CHECK(again.triangles == mesh.triangles);
  CHECK(again.nodes == mesh.nodes);
  CHECK(kit::irregular_rectangle_mesh(width, height, 16, 4, 1).nodes != mesh.nodes);
  CHECK_THROWS_AS(kit::irregular_rectangle_mesh(width, height, 16, 4, 1, 0.5), std::invalid_argument);
}
