#pragma once
// Liu, Bargteil, O'Brien & Kavan 2013, "Fast Simulation of Mass-Spring Systems": backward Euler
// in positions, x_{n+1} = argmin ½ (x − y)ᵀ M (x − y) + h² Σ_s ½ K_s (|x_a − x_b| − L0_s)²,
// y = x_n + h v_n + h² g, solved by alternating two steps a fixed number of times:
//   local:  each spring's direction d_s = L0_s (x_a − x_b)/|x_a − x_b| for the present x;
//   global: (M + h² L) x = M y + h² J d, L the springs' stiffness-weighted graph Laplacian.
// The global matrix does not change while h does not, so it is factorised once (sparse
// Cholesky, Eigen's SimplicialLDLT) and each iteration costs three triangular solve pairs, one
// per axis. Pins are eliminated (their positions move to the right side); springs model no
// damping (the method has none); drag c is backward Euler's too (the masses become M (1 + h c));
// contacts and the strain limit follow the step as in every other method.
#include <Eigen/SparseCholesky>

#include <kit/cloth/cloth_implicit_step.hpp>

namespace kit {

class LiuStepper : public ImplicitStepper {
 public:
  LiuStepper(const ClothSystem& cloth, int iterations);
  void step(ClothSystem& cloth, double h) override;

 private:
  void factorise(const ClothSystem& cloth, double h);

  int iterations_;
  std::vector<std::int32_t> free_;  ///< per node: its row in the global system, −1 when pinned
  Eigen::Index free_count_ = 0;
  double factorised_h_ = 0;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> cholesky_;
  Eigen::MatrixX3d y_, rhs_, solution_, d_;
};

}  // namespace kit
