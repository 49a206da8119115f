#pragma once
// Chapter 9's output of a deforming sheet: its triangles as a Wavefront OBJ mesh (Blender,
// MeshLab; read back by obj_mesh.hpp's reader), and its outline for the figures.
#include <filesystem>
#include <vector>

#include <kit/fem/fem_body.hpp>

namespace kit {

/// Writes the body's nodes (`v`, %.9g m) and triangles (`f a b c`, 1-based, counter-clockwise
/// at rest) atomically. Throws std::runtime_error when it cannot write.
void write_fem_obj(const std::filesystem::path& path, const FemBody& body);

/// The mesh's boundary as one closed loop of node indices, counter-clockwise at rest, first
/// node repeated at the end: the edges that belong to one triangle only, chained.
std::vector<int> boundary_loop(const TriangleMesh& mesh);

}  // namespace kit
