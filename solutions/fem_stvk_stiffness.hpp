#pragma once
// Ex 9.3: the element's stiffness ∂f/∂x (9×9, fem_element.hpp), which the implicit step needs
// (chapter 7's A = M − h² ∂f/∂x) and the static solve too. Differentiate the forces along a move
// dx of the nodes, one coordinate at a time:
//   dDs = [dx1 − dx0, dx2 − dx0],   dF = dDs Dm⁻¹,
//   dE = ½(dFᵀ F + Fᵀ dF),          dS = λ tr(dE) I + 2μ dE,
//   dP = dF S + F dS,               dH = −V dP Dm⁻ᵀ,   df0 = −(dh1 + dh2).
// Moving coordinate k of node a gives column 3a + k. The result is symmetric (the forces are an
// energy's gradient) and sends every rigid translation to zero.
#include <kit/base/not_implemented.hpp>
#include <kit/fem/fem_element.hpp>

namespace kit {

/// ∂f/∂x [N/m] of the St Venant–Kirchhoff element at deformation gradient F, with Dm⁻¹ [1/m],
/// rest volume V [m³] and Lamé's parameters [Pa]; rows and columns ordered (x0, y0, z0, x1, ...).
inline Matrix9 stvk_stiffness(const Matrix32& F, const Matrix2& rest_inverse, double rest_volume,
                              const Lame& lame) {
  // BEGIN SOLUTION ex 9.3: E and S at F; for each node a and axis k: dDs, dF, dE, dS, dP, dH as above → column 3a + k
  const Matrix2 identity = Matrix2::Identity();
  const Matrix2 E = 0.5 * (F.transpose() * F - identity);
  const Matrix2 S = lame.lambda * E.trace() * identity + 2 * lame.mu * E;
  Matrix9 K;
  for (int node = 0; node < 3; ++node)
    for (int axis = 0; axis < 3; ++axis) {
      Matrix32 dDs = Matrix32::Zero();
      if (node == 0)
        dDs.row(axis).setConstant(-1);
      else
        dDs(axis, node - 1) = 1;
      const Matrix32 dF = dDs * rest_inverse;
      const Matrix2 dE = 0.5 * (dF.transpose() * F + F.transpose() * dF);
      const Matrix2 dS = lame.lambda * dE.trace() * identity + 2 * lame.mu * dE;
      const Matrix32 dH = -rest_volume * (dF * S + F * dS) * rest_inverse.transpose();
      K.block<3, 1>(0, 3 * node + axis) = -(dH.col(0) + dH.col(1));
      K.block<6, 1>(3, 3 * node + axis) = Eigen::Map<const Eigen::Matrix<double, 6, 1>>(dH.data());
    }
  return K;
  // END SOLUTION
}

}  // namespace kit
