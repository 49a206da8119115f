#pragma once
// Ex 9.1: the deformation gradient and Green's strain of a linear triangle (lecture, "Mécanique des
// milieux continus"; fem_element.hpp). The rest edges Dm = [X1 − X0, X2 − X0] map to the current
// ones Ds = [x1 − x0, x2 − x0] by one linear map, the deformation gradient
//   F = Ds Dm⁻¹                   (3×2: a flat rest shape, current nodes anywhere in space)
// and Green's strain measures how F changes lengths, whatever way it turns the element:
//   E = ½(FᵀF − I)                (2×2, dimensionless; the lecture's ½(∇u + ∇uᵀ + ∇uᵀ∇u), ∇u = F − I)
// A rigid motion has FᵀF = I, so E = 0; a stretch by a along the rest x axis has E_xx = (a² − 1)/2.
#include <kit/base/not_implemented.hpp>
#include <kit/fem/fem_element.hpp>

namespace kit {

/// F [dimensionless] of the element whose current nodes are x0, x1, x2 [m], with Dm⁻¹ [1/m].
inline Matrix32 deformation_gradient(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                     const Matrix2& rest_inverse) {
  // BEGIN SOLUTION ex 9.1: Ds has the columns x1 − x0 and x2 − x0 (3×2); F = Ds · Dm⁻¹
  Matrix32 Ds;
  Ds << x1 - x0, x2 - x0;
  return Ds * rest_inverse;
  // END SOLUTION
}

/// Green's strain E = ½(FᵀF − I) [dimensionless, 2×2, symmetric].
inline Matrix2 green_strain(const Matrix32& F) {
  // BEGIN SOLUTION ex 9.1: FᵀF is 2×2; subtract the 2×2 identity and halve
  return 0.5 * (F.transpose() * F - Matrix2::Identity());
  // END SOLUTION
}

}  // namespace kit
