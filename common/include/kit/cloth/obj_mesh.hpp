#pragma once
// The cloth as a Wavefront OBJ mesh (chapter 6), for Blender or MeshLab: the nodes as vertices,
// smooth per-vertex normals and two triangles per grid cell. A small strict reader checks what
// was written.
#include <array>
#include <filesystem>
#include <vector>

#include <Eigen/Geometry>  // cross products of the vectors below

#include <kit/cloth/cloth.hpp>

namespace kit {

/// Per-node unit normals of the sheet at positions x (row i = node i [m]): the area-weighted
/// mean of the adjacent triangles' normals, each triangle oriented like the rest sheet's u×v
/// (cells split as in write_cloth_obj). A node whose triangles cancel or are degenerate (or not
/// finite) gets u×v normalised, or (0, 1, 0) when that is degenerate too.
/// Throws std::invalid_argument unless x has nx·ny rows and nx, ny ≥ 2.
NodeArray vertex_normals(const ClothGrid& grid, const NodeArray& x);

/// Writes the sheet at positions x [m] as an OBJ file, atomically (a temporary sibling renamed):
/// a comment header, one `v` (%.9g) and one `vn` line per node in node order, then per cell
/// (i, j) the triangles (i,j)-(i+1,j)-(i+1,j+1) and (i,j)-(i+1,j+1)-(i,j+1) as `f a//a b//b c//c`
/// (1-based), wound counter-clockwise seen from the side the u×v normal points to.
/// Throws std::invalid_argument as vertex_normals, std::runtime_error when it cannot write.
void write_cloth_obj(const std::filesystem::path& path, const ClothGrid& grid, const NodeArray& x);

/// A triangle mesh as read from an OBJ file; indices are 0-based.
struct ObjMesh {
  std::vector<Vec3> positions, normals;
  std::vector<std::array<int, 3>> faces;  ///< vertex indices; a vertex's normal has its index
};

/// Reads the OBJ subset write_cloth_obj writes: blank lines, `#` comments, `o`/`g`/`s` lines
/// (ignored), `v x y z`, `vn x y z` and triangles `f a b c` or `f a//a b//b c//c` with positive
/// indices of vertices (and normals) already defined. Throws std::runtime_error naming the file
/// and line for anything else: an unknown keyword, a missing, extra or malformed number, an index
/// out of range, a normal index that differs from its vertex index, or a file whose normals are
/// neither absent nor one per vertex.
ObjMesh read_obj(const std::filesystem::path& path);

}  // namespace kit
