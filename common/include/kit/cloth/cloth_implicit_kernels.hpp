#pragma once
// The three pieces of chapter 7's implicit step that the student writes (lecture, "Schéma
// implicite"; Baraff & Witkin 1998), as the kit calls them:
//   ex 7.1  the stiffness block of one spring, ∂f_a/∂x_a (3×3);
//   ex 7.2  the linear system A Δv = b of one step, in its symmetric form (ERRATA item 14):
//             A = M − h ∂f/∂v − h² ∂f/∂x,   b = h (f_n + h ∂f/∂x v_n);
//   ex 7.3  the modified (filtered) preconditioned conjugate gradient that solves it, with a
//           per-node constraint filter S (a pin S = 0, a node held on a plane S = I − nnᵀ).
// Vectors of the linear system interleave the axes: node i owns entries 3i, 3i + 1, 3i + 2.
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <kit/cloth/cloth.hpp>

namespace kit {

using Matrix3 =
    Mat3;  ///< the name before kit/base/vec3.hpp: kept one release for exercise copies that use it
/// The 3n×3n matrices of the implicit step, stored by rows.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// Ex 7.1: ∂f_a/∂x_a [N/m] of a spring from a (at xa [m]) to b (at xb), rest length `rest` [m],
/// stiffness K [N/m]. With x̂ the unit vector from b to a and l the length:
///   −K [x̂x̂ᵀ + (1 − L0/l)(I − x̂x̂ᵀ)],   (1 − L0/l) clamped to ≥ 0 when `clamp`.
/// ∂f_a/∂x_b = ∂f_b/∂x_a = −∂f_a/∂x_a, ∂f_b/∂x_b = ∂f_a/∂x_a.
using SpringStiffnessBlock = Mat3 (*)(const Vec3& xa, const Vec3& xb, double rest, double stiffness,
                                      bool clamp);

/// What ex 7.2 assembles A and b from: the state at the start of the step, its forces, and the
/// stiffness blocks ∂f_a/∂x_a of every spring (given, in spring order).
struct ImplicitSystemInput {
  const Springs& springs;
  const NodeArray& x;                  ///< positions [m]
  const NodeArray& v;                  ///< velocities [m/s]
  const NodeArray& f;                  ///< total force on each node at (x, v) [N]
  const Eigen::VectorXd& masses;       ///< [kg]
  const std::vector<Mat3>& stiffness;  ///< ∂f_a/∂x_a per spring [N/m]
  std::optional<double> drag;          ///< linear air drag c [1/s]: f = −m c v, so ∂f/∂v = −m c I
  double h = 0;                        ///< the step [s]
};
/// Ex 7.2: A [kg] (3n×3n, every entry of both triangles) and b [kg·m/s] (3n).
using ImplicitAssembly = void (*)(const ImplicitSystemInput& in, SparseMatrix& A, Eigen::VectorXd& b);

/// What a conjugate-gradient solve did.
struct PcgResult {
  Eigen::VectorXd x;                ///< the solution (Δv [m/s])
  int iterations = 0;               ///< products with A
  double residual = 0;              ///< ‖S(b − A x)‖ / ‖S b‖ at the end (0 when S b = 0)
  bool converged = false;           ///< residual ≤ tolerance
  bool negative_curvature = false;  ///< stopped because cᵀAc ≤ 0: A is not positive definite
};
/// Ex 7.3: solves S(A x − b) = 0 with x = S x, to ‖S(b − A x)‖ ≤ tolerance ‖S b‖, preconditioned
/// by diag(A), in at most max_iterations products with A. `filters` holds one S per node.
using FilteredPcg = PcgResult (*)(const SparseMatrix& A, const Eigen::VectorXd& b,
                                  const std::vector<Mat3>& filters, double tolerance, int max_iterations);

/// The student's three kernels, as the implicit step calls them.
struct ImplicitKernels {
  SpringStiffnessBlock stiffness_block = nullptr;  ///< ex 7.1: every step's Jacobian
  ImplicitAssembly assemble = nullptr;             ///< ex 7.2: checked against the kit's scatter
  FilteredPcg pcg = nullptr;                       ///< ex 7.3: the solver of --solver pcg
};

/// Node i's 3-vector in an interleaved vector, and the reverse.
inline Eigen::Map<const Vec3> node_of(const Eigen::VectorXd& flat, Eigen::Index i) {
  return Eigen::Map<const Vec3>(flat.data() + 3 * i);
}
Eigen::VectorXd flatten(const NodeArray& a);
void unflatten(const Eigen::VectorXd& flat, NodeArray& a);

}  // namespace kit
