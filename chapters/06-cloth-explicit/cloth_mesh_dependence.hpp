#pragma once
// The lecture's "Limitations: dépendance au maillage", measured: one physical sheet hanging under
// gravity, at rest, at several resolutions. How far the bottom edge drops depends on how the
// sheet is held and on how the spring stiffness follows the resolution.
#include <array>
#include <map>
#include <string>
#include <vector>

#include <kit/cloth/cloth_system.hpp>
#include <kit/ode/richardson.hpp>

namespace kit {

/// How the sheet hangs, and how its per-spring stiffness k follows the node count N.
enum class Hanging {
  top_edge,         ///< every node of the top edge pinned; k the same at every N
  corner_nodes,     ///< the two top corner nodes pinned; k the same at every N
  corner_segments,  ///< the top edge's outer eighths pinned on each side (a fixed physical
                    ///< length, more nodes as N grows); k the same at every N
  top_edge_k_by_n,  ///< the top edge pinned, k ∝ N: the rule for a chain of springs (a rope)
                    ///< carried over to the sheet
};
inline constexpr Hanging all_hangings[] = {Hanging::top_edge, Hanging::corner_nodes, Hanging::corner_segments,
                                           Hanging::top_edge_k_by_n};
const char* describe(Hanging hanging);

/// The hanging sheet: 1 m × 1 m, 0.2 kg/m², structural and shear springs of stiffness k [N/m]
/// at N = 8 (scaled by N/8 for top_edge_k_by_n), gravity −9.81 m/s², at N × N nodes.
ClothScene hanging_sheet(int n, Hanging hanging, double k = 50);

/// The sheet at rest, found by dynamic relaxation: symplectic Euler (ex 6.3) at 0.9 of its
/// Δt_max, with air drag of 5/s, until no node moves faster than 1e-6 m/s (the drag then
/// leaves at most 1e-6/5 m = 0.2 µm to go).
struct Sag {
  int n = 0;
  double drop = 0;         ///< how far the middle of the bottom edge sits below its rest place [m]
  double peak_strain = 0;  ///< the largest structural stretch at rest
  long steps = 0;
  bool settled = false;  ///< false: the step budget ran out first
};
Sag hanging_sag(int n, Hanging hanging, ClothKernels kernels, long max_steps = 400000);

/// "converges at order 1.03 to 12.48 mm, 0.8% away at N = 64", or that it does not over the
/// three resolutions `n` (coarse to fine); the limit shown times `unit` in `unit_name`.
std::string describe(const Convergence& c, const std::array<int, 3>& n, double unit,
                     const std::string& unit_name);

/// The chapter's experiment: every way of holding the sheet at N = 8, 16, 32, … up to `finest_n`
/// (the chapter's 64; at least 32), and Richardson's estimate for the top edge from the finest
/// three.
struct MeshDependence {
  std::map<Hanging, std::vector<Sag>> sags;
  std::array<int, 3> finest{};  ///< the N of Richardson's three runs
  Convergence top_edge;
};
MeshDependence measure_mesh_dependence(ClothKernels kernels, int finest_n = 64);

}  // namespace kit
