#pragma once
// Chapter 9's deformable sheet: a triangle mesh (fem_mesh.hpp) whose nodes carry lumped masses
// and move in 3-D, held together by one of three models of the same material:
//   linear   the small-strain finite element (Cauchy strain; a plate in its plane only),
//   stvk     St Venant–Kirchhoff finite elements on Green's strain (ex 9.1 to 9.3),
//   springs  one spring per mesh edge (chapter 6's ex 6.1 and chapter 7's ex 7.1), of stiffness
//            k = E t ΣA / |e|², the sum over the one or two triangles beside edge e (Van Gelder's
//            rule, 1998): the mass–spring model whose answer depends on the mesh.
// Nodes are held by 3×3 filters (chapter 7): I free, 0 pinned, diag(1, 1, 0) in the plane z = 0.
// Vectors of the linear systems interleave the axes (node i owns entries 3i to 3i + 2).
#include <string>
#include <vector>

#include <kit/base/enum_names.hpp>
#include <kit/cloth/cloth_implicit_kernels.hpp>
#include <kit/cloth/cloth_system.hpp>
#include <kit/fem/fem_element.hpp>
#include <kit/fem/fem_mesh.hpp>

namespace kit {

enum class FemModel { linear, stvk, springs };
/// Their names in --model, summaries and figures.
inline constexpr auto fem_model_names = enum_names<FemModel>({
    {FemModel::linear, "linear", "linear"},
    {FemModel::stvk, "stvk", "stvk"},
    {FemModel::springs, "springs", "springs"},
});
static_assert(fem_model_names.in_order());
inline const char* model_name(FemModel model) { return fem_model_names.flag(model); }

/// The sheet's material: Young's modulus [Pa], Poisson's ratio, density [kg/m³], thickness [m].
struct FemMaterial {
  double young = 1e9;
  double poisson = 0.3;
  double density = 1000;
  double thickness = 0.01;
};

/// Every student kernel the sheet can call: the element (ex 9.1 to 9.3), the spring (ex 6.1),
/// its stiffness block (ex 7.1) and the filtered PCG of the implicit step (ex 7.3).
struct ContinuumKernels {
  FemKernels element;
  SpringForce spring_force = nullptr;
  SpringStiffnessBlock spring_stiffness = nullptr;
  FilteredPcg pcg = nullptr;
};

class FemBody {
 public:
  /// The mesh at rest in the plane z = 0, every node free. Throws std::invalid_argument for a
  /// material out of range (Lamé's ranges, a non-positive density or thickness) or a degenerate
  /// triangle.
  FemBody(TriangleMesh mesh, const FemMaterial& material, FemModel model, const ContinuumKernels& kernels);

  long nodes() const { return static_cast<long>(mesh_.nodes.size()); }
  long elements() const { return static_cast<long>(mesh_.triangles.size()); }
  FemModel model() const { return model_; }
  const TriangleMesh& mesh() const { return mesh_; }
  const Lame& lame() const { return lame_; }
  const FemMaterial& material() const { return material_; }
  const ContinuumKernels& kernels() const { return kernels_; }
  const Springs& springs() const { return springs_; }

  void pin(long node) { filters[node].setZero(); }
  /// Keeps every node in the plane z = 0 (pins stay pinned).
  void hold_in_plane();

  /// The total force on every node [N]: the model's internal forces, the loads, and a drag
  /// −m c v of c [1/s].
  void forces(NodeArray& out, double drag = 0) const;
  /// ∂f/∂x of the internal forces [N/m], 3n×3n, both triangles stored. Scattered into the
  /// sparsity pattern the body found once (a 3×3 block for every pair of nodes an element or a
  /// spring joins): `out` takes that pattern the first time and keeps it, so the next calls with
  /// the same `out` neither allocate nor sort.
  void stiffness(SparseMatrix& out) const;
  /// The deformation gradient F of element t, by ex 9.1.
  Matrix32 gradient(std::size_t t) const;
  /// The model's stored energy [J] (the linear model's is ½ V σ:ε per element).
  double elastic_energy() const;
  /// How far each element is from its rest shape, the largest |E| (Frobenius) over elements.
  double largest_green_strain() const;

  NodeArray x, v;             ///< positions [m], velocities [m/s]
  NodeArray loads;            ///< external forces (gravity, tractions) [N], constant
  Eigen::VectorXd masses;     ///< lumped: each triangle gives ρ V / 3 to each corner [kg]
  std::vector<Mat3> filters;  ///< per node, the directions it may move in

 private:
  TriangleMesh mesh_;
  FemMaterial material_;
  FemModel model_;
  ContinuumKernels kernels_;
  Lame lame_;
  std::vector<RestTriangle> rest_;
  Springs springs_;                        ///< the springs model's edges
  std::vector<Matrix9> linear_stiffness_;  ///< the linear model's, per element: the same at every state
  SparseMatrix pattern_;                   ///< the stiffness's sparsity pattern, values zero
  std::vector<int> slots_;  ///< where each block row starts in the values: 27 an element, 12 a spring
};

/// Gravity g [m/s²] along −y on every node's mass.
void add_weight(FemBody& body, double gravity = 9.81);

/// The coordinates the filters leave free (the filters here are diagonal, 0 or 1), as indices
/// 3i + axis into the interleaved vectors.
std::vector<int> free_coordinates(const FemBody& body);
/// |f| over the free coordinates / |loads|: how far the body is from balancing its loads.
double load_residual(const FemBody& body);

}  // namespace kit
