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

#include <kit/cloth_implicit_kernels.hpp>
#include <kit/fem_element.hpp>
#include <kit/fem_mesh.hpp>
#include <kit/spring_force_check.hpp>

namespace kit {

enum class FemModel { linear, stvk, springs };
const char* model_name(FemModel model);

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
  /// ∂f/∂x of the internal forces [N/m], 3n×3n.
  void stiffness(SparseMatrix& out) const;
  /// The model's stored energy [J] (the linear model's is ½ V σ:ε per element).
  double elastic_energy() const;
  /// How far each element is from its rest shape, the largest |E| (Frobenius) over elements.
  double largest_green_strain() const;

  NodeArray x, v;                 ///< positions [m], velocities [m/s]
  NodeArray loads;                ///< external forces (gravity, tractions) [N], constant
  Eigen::VectorXd masses;         ///< lumped: each triangle gives ρ V / 3 to each corner [kg]
  std::vector<Matrix3> filters;   ///< per node, the directions it may move in

 private:
  TriangleMesh mesh_;
  FemMaterial material_;
  FemModel model_;
  ContinuumKernels kernels_;
  Lame lame_;
  std::vector<RestTriangle> rest_;
  Springs springs_;  ///< the springs model's edges
  std::vector<Matrix9> linear_stiffness_;  ///< the linear model's, per element: the same at every state
};

/// Gravity g [m/s²] along −y on every node's mass.
void add_weight(FemBody& body, double gravity = 9.81);

/// The body's rest state under its loads, by Newton's method on the free coordinates with a
/// sparse direct solver (LDLᵀ): each step solves −K Δx = f. The linear model converges in one
/// step. Converged when |f| on the free coordinates ≤ tolerance × |loads|, or at round-off: when
/// a step moved no coordinate by more than 1e-9 of the largest in-plane displacement; fails on a
/// step that is not finite, or a singular K. When the whole load fails (a large deflection, far
/// from the start), it is applied again from rest in 4, 16 and then 64 equal increments, each
/// solved from the last: a continuation along the load.
struct StaticSolve {
  int iterations = 0;   ///< Newton steps, over every increment
  int increments = 1;   ///< the load steps of the attempt that is reported
  double residual = 0;  ///< |f_free| / |loads| at the end
  bool converged = false;
  std::string failure;  ///< why not, when not
};
StaticSolve solve_static(FemBody& body, int max_iterations = 40, double tolerance = 1e-10);

/// One step of symplectic Euler [s]: v += h M⁻¹ f (filtered), x += h v.
void explicit_step(FemBody& body, double h, double drag);
/// The largest stable explicit step of the body at rest, 2/ω_max, with ω_max bounded above by
/// Gershgorin's bound on M⁻¹K (so the step is safe, within a factor of about two).
double explicit_step_limit(const FemBody& body);

/// One step of implicit Euler [s] (Baraff & Witkin 1998, chapter 7's form):
///   (M (1 + h c) − h² K) Δv = h (f + h K v),   v += Δv,   x += h v,
/// solved by the filtered PCG (ex 7.3) to `tolerance`. Reports the solver's iterations and
/// whether it converged (it may not, if K is indefinite: a compressed St Venant–Kirchhoff element).
struct ImplicitStep {
  int iterations = 0;
  bool converged = false;
};
ImplicitStep implicit_step(FemBody& body, double h, double drag, double tolerance = 1e-8, int max_iterations = 20000);

}  // namespace kit
