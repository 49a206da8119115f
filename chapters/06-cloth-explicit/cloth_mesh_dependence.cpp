// The hanging sheet at several resolutions (cloth_mesh_dependence.hpp).
#include "cloth_mesh_dependence.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include <kit/cloth/cloth_stability.hpp>

namespace kit {

const char* describe(Hanging hanging) {
  switch (hanging) {
    case Hanging::top_edge:
      return "top edge pinned, same k";
    case Hanging::corner_nodes:
      return "two corner nodes pinned, same k";
    case Hanging::corner_segments:
      return "two corner eighths pinned, same k";
    case Hanging::top_edge_k_by_n:
      return "top edge pinned, k ∝ N (a rope's rule)";
  }
  return "";
}

ClothScene hanging_sheet(int n, Hanging hanging, double k) {
  ClothScene scene;
  scene.name = "hanging sheet";
  scene.grid.nx = scene.grid.ny = n;
  scene.grid.width = scene.grid.height = 1;
  scene.grid.areal_density = 0.2;
  scene.grid.origin = {0, 1, 0}, scene.grid.u = {1, 0, 0}, scene.grid.v = {0, -1, 0};  // row 0 on top
  const double stiffness = hanging == Hanging::top_edge_k_by_n ? k * n / 8.0 : k;
  scene.springs.structural = SpringFamily{stiffness, 0};
  scene.springs.shear = SpringFamily{stiffness, 0};
  scene.gravity = Vec3(0, -9.81, 0);
  for (int i = 0; i < n; ++i) {
    const double along = double(i) / (n - 1);  // position on the top edge, 0 to 1
    const bool pinned =
        hanging == Hanging::top_edge || hanging == Hanging::top_edge_k_by_n ||
        (hanging == Hanging::corner_nodes && (i == 0 || i == n - 1)) ||
        (hanging == Hanging::corner_segments && (along <= 0.125 + 1e-12 || along >= 0.875 - 1e-12));
    if (pinned) scene.pins.push_back({i, 0});
  }
  return scene;
}

Sag hanging_sag(int n, Hanging hanging, ClothKernels kernels, long max_steps) {
  ClothScene scene = hanging_sheet(n, hanging);
  const Springs springs = kernels.build_springs(scene.grid, scene.springs);
  ClothSystem rest(scene, springs, kernels);
  const double dt = 0.9 * predicted_dt_max(ClothIntegrator::symplectic_euler,
                                           omega_max(springs, rest.masses(), rest.x, rest.pins()).omega);
  scene.drag = 5.0;  // [1/s]: damps the sheet's slow swinging and stretching modes in a few seconds
  ClothSystem cloth(scene, springs, kernels);
  Sag sag{n, 0, 0, 0, false};
  while (sag.steps < max_steps && !sag.settled) {
    for (int k = 0; k < 500; ++k) cloth.step(ClothIntegrator::symplectic_euler, dt);
    sag.steps += 500;
    sag.settled = cloth.v.cwiseAbs().maxCoeff() < 1e-6;
  }
  // The middle of the bottom edge: one node when n is odd, the mean of the two middle ones else.
  const long left = scene.grid.index((n - 1) / 2, n - 1), right = scene.grid.index(n / 2, n - 1);
  const NodeArray rest_x = scene.grid.rest_positions();
  sag.drop = 0.5 * (rest_x(left, 1) + rest_x(right, 1) - cloth.x(left, 1) - cloth.x(right, 1));
  sag.peak_strain = cloth.max_strain();
  return sag;
}

MeshDependence measure_mesh_dependence(ClothKernels kernels, int finest_n) {
  if (finest_n < 32)
    throw std::invalid_argument("measure_mesh_dependence: Richardson needs N = 8, 16 and 32 at least");
  MeshDependence m;
  for (Hanging hanging : all_hangings)
    for (int n = 8; n <= finest_n; n *= 2) m.sags[hanging].push_back(hanging_sag(n, hanging, kernels));
  const auto& edge = m.sags[Hanging::top_edge];
  const std::size_t last = edge.size() - 1;
  m.finest = {edge[last - 2].n, edge[last - 1].n, edge[last].n};
  m.top_edge = richardson(edge[last - 2].drop, edge[last - 1].drop, edge[last].drop);
  return m;
}

std::string describe(const Convergence& c, const std::array<int, 3>& n, double unit,
                     const std::string& unit_name) {
  if (!c.converges)
    return fmt::format("does not converge over N = {}, {}, {} (the differences do not shrink)", n[0], n[1],
                       n[2]);
  return fmt::format("converges at order {:.2f} to {:.4g} {}, {:.2g}% away at N = {}", c.order,
                     unit * c.limit, unit_name, 100 * c.remaining, n[2]);
}

}  // namespace kit
