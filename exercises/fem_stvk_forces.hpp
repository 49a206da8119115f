#pragma once
// Ex 9.2: St Venant–Kirchhoff's stress and the element's forces (fem_element.hpp). The material
// answers Green's strain E with the second Piola–Kirchhoff stress
//   S = λ tr(E) I + 2μ E                                           [Pa]
// (Hooke's law in Lamé's form, applied to E instead of the small strain). The force on a node is
// minus the energy's gradient; for the linear triangle it comes out as
//   H = −V P Dm⁻ᵀ,  P = F S     (3×2: the forces on nodes 1 and 2, as columns)   [N]
//   f0 = −(f1 + f2)             (no net force: a translation stores no energy)
// with V the rest volume. This exercise computes E from F itself (one line), so that it can be
// graded without ex 9.1.
#include <kit/base/not_implemented.hpp>
#include <kit/fem/fem_element.hpp>

namespace kit {

/// S [Pa] for the Green strain E and Lamé's λ, μ [Pa].
inline Matrix2 stvk_stress(const Matrix2& E, const Lame& lame) {
  // TODO(ex 9.2): λ times the trace of E times the 2×2 identity, plus 2μ E
  throw kit::NotImplemented("ex 9.2", "fem_stvk_forces.hpp");
}

/// The forces [N] on the element's three nodes (column i on node i) at deformation gradient F,
/// with Dm⁻¹ [1/m], rest volume V [m³] and Lamé's parameters [Pa].
inline ElementForces stvk_forces(const Matrix32& F, const Matrix2& rest_inverse, double rest_volume,
                                 const Lame& lame) {
  // TODO(ex 9.2): E = ½(FᵀF − I); S from stvk_stress; H = −V (F S) Dm⁻ᵀ; columns f0 = −(h1 + h2), h1, h2
  throw kit::NotImplemented("ex 9.2", "fem_stvk_forces.hpp");
}

}  // namespace kit
