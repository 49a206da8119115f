#include <kit/fem_element.hpp>

#include <cmath>
#include <stdexcept>

#include <Eigen/LU>
#include <fmt/format.h>

namespace kit {

RestTriangle rest_triangle(const Eigen::Vector2d& X0, const Eigen::Vector2d& X1, const Eigen::Vector2d& X2,
                           double thickness) {
  if (!(thickness > 0) || !std::isfinite(thickness))
    throw std::invalid_argument(fmt::format("thickness {} m: expected a positive finite number", thickness));
  Matrix2 edges;
  edges << X1 - X0, X2 - X0;
  const double twice_area = edges.determinant();
  // A triangle thinner than round-off of its own size has no usable Dm⁻¹.
  const double scale = (X1 - X0).squaredNorm() + (X2 - X0).squaredNorm();
  if (!(twice_area > 1e-12 * scale))
    throw std::invalid_argument(fmt::format("rest triangle ({}, {}) ({}, {}) ({}, {}): degenerate or clockwise",
                                            X0.x(), X0.y(), X1.x(), X1.y(), X2.x(), X2.y()));
  return {edges.inverse(), 0.5 * twice_area * thickness};
}

Matrix2 cauchy_strain(const Matrix32& F) {
  const Matrix2 G = F.topRows<2>();
  return 0.5 * (G + G.transpose()) - Matrix2::Identity();
}

namespace {

/// The nodal forces of a plate whose in-plane stress is σ [Pa]: −V [σ; 0] Dm⁻ᵀ on nodes 1, 2.
ElementForces plane_stress_forces(const Matrix2& sigma, const Matrix2& rest_inverse, double rest_volume) {
  Matrix32 P = Matrix32::Zero();
  P.topRows<2>() = sigma;
  const Matrix32 H = -rest_volume * P * rest_inverse.transpose();
  ElementForces f;
  f << -(H.col(0) + H.col(1)), H;
  return f;
}

Matrix2 hooke(const Matrix2& strain, const Lame& lame) {
  return lame.lambda * strain.trace() * Matrix2::Identity() + 2 * lame.mu * strain;
}

}  // namespace

ElementForces linear_forces(const Matrix32& F, const Matrix2& rest_inverse, double rest_volume, const Lame& lame) {
  return plane_stress_forces(hooke(cauchy_strain(F), lame), rest_inverse, rest_volume);
}

Matrix9 linear_stiffness(const Matrix2& rest_inverse, double rest_volume, const Lame& lame) {
  // The model is linear in the positions: the forces of a unit move of each coordinate, less the
  // forces at the rest shape (which are zero there), are the stiffness's columns.
  Matrix9 K = Matrix9::Zero();
  for (int node = 0; node < 3; ++node)
    for (int axis = 0; axis < 2; ++axis) {
      Matrix32 dDs = Matrix32::Zero();  // how Ds = [x1 − x0, x2 − x0] moves with x_node[axis]
      if (node == 0) dDs.row(axis).setConstant(-1);
      else dDs(axis, node - 1) = 1;
      const Matrix2 dG = (dDs * rest_inverse).topRows<2>();
      const Matrix2 d_epsilon = 0.5 * (dG + dG.transpose());
      const ElementForces df = plane_stress_forces(hooke(d_epsilon, lame), rest_inverse, rest_volume);
      K.col(3 * node + axis) = df.reshaped();
    }
  return K;
}

}  // namespace kit
