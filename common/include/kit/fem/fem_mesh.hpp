#pragma once
// Chapter 9's meshes (lecture, "Mécanique des milieux continus"): a rectangle cut into linear
// triangles, regularly (each cell split along one diagonal or the other, or alternating) or
// irregularly (the regular grid's boundary nodes, its interior nodes moved by a deterministic
// jitter, then a Delaunay triangulation). The same domain and the same nodes on its boundary in
// every mesh, so that a load or a support sits at the same places whatever the triangulation:
// what changes between them is only how the inside is cut, which is what the lecture's
// "dépendance au maillage" of mass–spring models is about.
#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace kit {

struct TriangleMesh {
  std::vector<Eigen::Vector2d> nodes;         ///< rest positions [m]
  std::vector<std::array<int, 3>> triangles;  ///< node indices, counter-clockwise
};

/// How a regular mesh splits each cell: along the diagonal rising to the right, falling to the
/// right, or alternating between the two like a checkerboard (no preferred direction).
enum class CellDiagonal { rising, falling, alternating };

/// The rectangle [0, width] × [0, height] [m] as nx × ny cells (nodes (nx + 1) × (ny + 1), row by
/// row from (0, 0)), two triangles a cell. Throws std::invalid_argument unless the sizes are
/// positive and finite and nx, ny ≥ 1.
TriangleMesh regular_rectangle_mesh(double width, double height, int nx, int ny, CellDiagonal diagonal);

/// The same rectangle and boundary nodes as regular_rectangle_mesh, its interior nodes each moved
/// by up to `jitter` of a cell along each axis (in [0, 0.45], so that no two nodes meet), drawn from
/// `seed` (the same seed, the same mesh, on every machine), then made Delaunay by Lawson's edge
/// flips from the regular mesh: no node lies inside another triangle's circumcircle.
TriangleMesh irregular_rectangle_mesh(double width, double height, int nx, int ny, std::uint64_t seed,
                                      double jitter = 0.3);

/// The signed area of triangle t [m²]: positive when counter-clockwise.
double triangle_area(const TriangleMesh& mesh, int t);

}  // namespace kit
