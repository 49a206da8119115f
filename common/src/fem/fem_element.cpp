#include <kit/fem/fem_element.hpp>

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <Eigen/LU>

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
    throw std::invalid_argument(
        fmt::format("rest triangle ({}, {}) ({}, {}) ({}, {}): degenerate or clockwise", X0.x(), X0.y(),
                    X1.x(), X1.y(), X2.x(), X2.y()));
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
  f.rightCols<2>() = H;
  f.col(0) = -H.rowwise().sum();  // no net force
  return f;
}

}  // namespace

Matrix2 linear_stress(const Matrix2& strain, const Lame& lame) {
  return lame.lambda * strain.trace() * Matrix2::Identity() + 2 * lame.mu * strain;
}

ElementForces linear_forces(const Matrix32& F, const Matrix2& rest_inverse, double rest_volume,
                            const Lame& lame) {
  return plane_stress_forces(linear_stress(cauchy_strain(F), lame), rest_inverse, rest_volume);
}

Matrix9 linear_stiffness(const Matrix2& rest_inverse, double rest_volume, const Lame& lame) {
  // The model is linear in the positions and has no force at rest: the forces with one coordinate
  // moved by 1 m from the rest shape are the stiffness's columns. The rest shape, with X0 at the
  // origin: X1 and X2 are the columns of Dm.
  const Matrix2 rest_edges = rest_inverse.inverse();
  Matrix9 K = Matrix9::Zero();
  for (int node = 0; node < 3; ++node)
    for (int axis = 0; axis < 2; ++axis) {
      Vec3 x[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
      x[1].head<2>() = rest_edges.col(0);
      x[2].head<2>() = rest_edges.col(1);
      x[node][axis] += 1;
      Matrix32 moved_edges;
      moved_edges.col(0) = x[1] - x[0];
      moved_edges.col(1) = x[2] - x[0];
      K.col(3 * node + axis) =
          linear_forces(moved_edges * rest_inverse, rest_inverse, rest_volume, lame).reshaped();
    }
  return K;
}

}  // namespace kit
