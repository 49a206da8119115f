#pragma once
// Geometric multigrid on a cloth's grid, the preconditioner of chapter 7's fastest solver
// (--solver mg). Diagonal-preconditioned CG needs about √κ iterations, and κ of the implicit
// matrix grows like h² K / m times the grid's size: on the bench's stiff 81×81 sheet that is a
// thousand iterations a step. One multigrid V-cycle removes the error at every wavelength at
// once, fine waves by smoothing and long waves on coarser grids: CG preconditioned by it needs
// about ten there. Its count still grows on fine grids at extreme stiffness (bilinear
// interpolation misses a stiff sheet's soft bending shapes), far more slowly than CG's.
//
//   - Levels: the grid's even-numbered nodes (and its last) make the next coarser grid, down to
//     at most 6×6 nodes; a fine node takes the bilinear average of its coarse neighbours (P).
//   - Coarse operators: A_c = Pᵀ A P (Galerkin), built each step from that step's A through a
//     plan made once per mesh: no search, no sort.
//   - Smoother: node-block Gauss–Seidel (3×3 blocks), forward before the coarse correction and
//     backward after it, so that the cycle is a symmetric positive definite operator, as CG
//     needs; the coarsest grid is solved exactly (dense Cholesky).
//   - Precision: the cycle in single precision, CG in double (mixed precision: a preconditioner
//     only steers the search, the residual CG tests is computed in double).
//
// Either the cloth's own multigrid_pcg below, with Baraff & Witkin's filters, or any CG that
// takes a preconditioner can use it.
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/StdVector>

#include <kit/cloth/cloth_implicit_kernels.hpp>

namespace kit {

class GridMultigrid {
 public:
  /// Levels for nx × ny nodes (node j·nx + i) and the pattern of the implicit matrix: a 3×3
  /// block for each node and each node it is joined to, node i's three rows holding the same
  /// block columns in order (ImplicitMatrix's). Throws std::invalid_argument otherwise.
  GridMultigrid(int nx, int ny, const SparseMatrix& pattern);

  /// Takes this step's A (same pattern): the coarse operators Pᵀ A P, the inverses of the
  /// diagonal blocks, the coarsest Cholesky factor. False when A is seen not to be positive
  /// definite (a diagonal block with no finite inverse, or a coarsest matrix Cholesky rejects):
  /// the cycle is then no preconditioner for CG.
  bool setup(const SparseMatrix& A);
  /// z = B r, one V(1,1)-cycle from zero: B ≈ A⁻¹, symmetric positive definite (to the
  /// rounding of single precision, in which the cycle runs: it only has to point CG the right way,
  /// and half the bytes make it twice as fast; CG itself stays in double).
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z);

  int levels() const { return int(levels_.size()); }
  int level_nodes(int level) const { return levels_[std::size_t(level)].nodes(); }
  /// 3×3 blocks stored on a level (the finest: A's).
  long level_blocks(int level) const { return long(levels_[std::size_t(level)].column.size()); }

 private:
  /// A 3×3 block column by column, each column padded to four floats (the fourth row zero), so
  /// that a block times a node's vector is three four-wide multiply-adds.
  using Block = Eigen::Matrix<float, 4, 3>;
  /// A node's 3-vector, padded the same way (its fourth entry stays zero).
  using Node = Eigen::Vector4f;
  template <class T>
  using Aligned = std::vector<T, Eigen::aligned_allocator<T>>;

  struct Level {
    int nx = 0, ny = 0;
    int nodes() const { return nx * ny; }
    // Node i's blocks: column[first[i] .. first[i + 1]) and values[first[i] .. first[i + 1]);
    // diagonal[i] is the position of its own block among them.
    std::vector<int> first, column, diagonal;
    Aligned<Block> values, inverse_diagonal;
    // Prolongation to this level from the next coarser: fine node i takes weight[k] of coarse
    // node parent[k] for k in [parent_first[i], parent_first[i + 1]).
    std::vector<int> parent_first, parent;
    std::vector<float> weight;
    // Pᵀ A P: block e of this level, times term_weight[t], is added to the coarser level's block
    // term_target[t], for t in [term_first[e], term_first[e + 1]).
    std::vector<int> term_first, term_target;
    std::vector<float> term_weight;
    Aligned<Node> x, b, r;
  };

  void add_coarser_level();
  static Node row_product(const Level& level, int i, int begin, int end);
  static void smooth(Level& level, bool forward, bool from_zero);
  static void residual_after_forward_sweep(Level& level);
  void cycle(std::size_t l);

  std::vector<Level> levels_;
  std::vector<int> csr_first_;  ///< per node of the finest level: where its rows start in A's values
  Eigen::MatrixXd coarsest_matrix_;
  Eigen::LLT<Eigen::MatrixXd> coarsest_;
  Eigen::VectorXd coarsest_b_;
};

/// Baraff & Witkin's filtered CG (ex 7.3's method and report) preconditioned by one V-cycle of
/// `multigrid` instead of diag(A): solves S(A x − b) = 0 with x = S x, to ‖S(b − A x)‖ ≤
/// tolerance ‖S b‖, from x = 0. `multigrid` must have been set up with A. Counts its products
/// with A (it applies as many V-cycles). negative_curvature also reports a search direction on
/// which the cycle itself is not positive (rᵀ S B S r ≤ 0).
PcgResult multigrid_pcg(const SparseMatrix& A, const Eigen::VectorXd& b, const std::vector<Mat3>& filters,
                        GridMultigrid& multigrid, double tolerance, int max_iterations);

}  // namespace kit
