#pragma once
// The matrix of chapter 7's implicit step, A = M − h ∂f/∂v − h² ∂f/∂x (ERRATA item 14), built
// the way a production solver builds it: its sparsity pattern once per mesh (a 3×3 block for
// every node and for every pair of nodes a spring joins), then every step scatters the springs'
// blocks straight into the preallocated values, with no allocation and no sort. Ex 7.2 builds
// the same matrix from triplets, the straightforward way the chapter times it against.
#include <cstdint>
#include <optional>
#include <vector>

#include <kit/cloth/cloth_implicit_kernels.hpp>

namespace kit {

/// The damping block of one spring, ∂f_a/∂v_a = −μ x̂x̂ᵀ [N·s/m] (damping along the spring only;
/// zero for a spring of zero length, which has no direction).
Mat3 spring_damping_block(const Vec3& xa, const Vec3& xb, double damping);

/// ∂f/∂x · w for the springs whose stiffness blocks are given: spring s adds J_s (w_a − w_b) to
/// node a and the opposite to node b. Result interleaved (3n).
void stiffness_times(const Springs& springs, const std::vector<Mat3>& stiffness, const NodeArray& w,
                     Eigen::VectorXd& out);

class ImplicitMatrix {
 public:
  /// The pattern of the springs' mesh over `nodes` nodes; `pins` are the nodes whose rows and
  /// columns constrain() replaces.
  ImplicitMatrix(const Springs& springs, long nodes, const std::vector<std::int32_t>& pins);

  /// A for the state x with the given stiffness blocks (one per spring), masses [kg], drag [1/s]
  /// and step h [s], scattered into `matrix`'s values.
  void assemble(const Springs& springs, const NodeArray& x, const std::vector<Mat3>& stiffness,
                const Eigen::VectorXd& masses, std::optional<double> drag, double h);

  /// Pins by elimination, for a solver without filters: a pinned node's rows and columns keep
  /// only their diagonal entries, and its entries of b become zero, so its Δv is exactly zero
  /// and no other node's equation sees it move.
  void constrain(Eigen::VectorXd& b);

  SparseMatrix matrix;  ///< 3n×3n, both triangles stored

 private:
  // For spring s, where its blocks start in the values: block (a, b) of row 3a + r starts at
  // outer[3a + r] + 3·column_[s].ab, and so on. One position serves the block's three rows.
  struct SpringSlots {
    std::int32_t aa, ab, ba, bb;
  };
  std::vector<SpringSlots> slots_;
  std::vector<std::int32_t> diagonal_;       ///< per node: the position of its own block in its rows
  std::vector<std::int64_t> pinned_values_;  ///< value indices in pinned rows or columns, off the diagonal
  std::vector<std::int32_t> pins_;
};

}  // namespace kit
