#pragma once
// Chapter 9's finite element (lecture, "Mécanique des milieux continus"): the linear triangle, as
// a membrane in 3-D. Its rest shape is a triangle X0 X1 X2 in the plane [m]; its current nodes
// x0 x1 x2 may lie anywhere in space (a plate in the plane z = 0 is the special case where they
// stay there). With the edge matrices Dm = [X1 − X0, X2 − X0] (2×2) and Ds = [x1 − x0, x2 − x0]
// (3×2), the displacement is linear over the element and its deformation gradient constant:
//   F = Ds Dm⁻¹                                                      (3×2, dimensionless)
// Green's strain E = ½(FᵀF − I) (2×2) is the lecture's ε = ½(∇u + ∇uᵀ + ∇uᵀ∇u) with ∇u = F − I
// (errata 16), and it is zero for every rigid motion. St Venant–Kirchhoff's second Piola–Kirchhoff
// stress is S = λ tr(E) I + 2μ E [Pa], the first P = F S, the energy W = V (μ E:E + ½λ tr(E)²)
// [J] with V the rest volume (area × thickness), and the forces on nodes 1 and 2 are the columns
// of H = −V P Dm⁻ᵀ, the force on node 0 their opposite sum. Nine-vectors and 9×9 matrices order
// the unknowns node by node: (x0, y0, z0, x1, ...).
//
// The student writes the element (ex 9.1 to 9.3); the kit calls it through FemKernels and keeps
// here what is not an exercise: the rest shape and the linear (Cauchy) model that the chapter
// shows failing under rotation. The energy is not offered here: ex 9.2 is graded against its
// derivative, and a library energy would let the forces come from differences of it.
#include <Eigen/Core>

#include <kit/base/vec3.hpp>
#include <kit/fem/fem_material.hpp>

namespace kit {

using FemVector3 =
    Vec3;  ///< the name before kit/base/vec3.hpp: kept one release for exercise copies that use it
using Matrix32 = Eigen::Matrix<double, 3, 2>;
using Matrix2 = Eigen::Matrix2d;
using ElementForces = Eigen::Matrix3d;  ///< column i: the force on node i [N]
using Vector9 = Eigen::Matrix<double, 9, 1>;
using Matrix9 = Eigen::Matrix<double, 9, 9>;

/// What an element keeps of its rest shape: Dm⁻¹ [1/m] and the rest volume V = area × thickness [m³].
struct RestTriangle {
  Matrix2 inverse;
  double volume = 0;
};
/// The rest shape of X0 X1 X2 [m] (counter-clockwise) with thickness [m]. Throws
/// std::invalid_argument if the triangle is degenerate or clockwise, or the thickness not positive.
RestTriangle rest_triangle(const Eigen::Vector2d& X0, const Eigen::Vector2d& X1, const Eigen::Vector2d& X2,
                           double thickness);

/// Ex 9.1: F = Ds Dm⁻¹ from the current nodes [m] and Dm⁻¹ [1/m].
using DeformationGradient = Matrix32 (*)(const Vec3& x0, const Vec3& x1, const Vec3& x2,
                                         const Matrix2& rest_inverse);
/// Ex 9.1: Green's strain E = ½(FᵀF − I).
using GreenStrain = Matrix2 (*)(const Matrix32& F);
/// Ex 9.2: St Venant–Kirchhoff's S = λ tr(E) I + 2μ E [Pa].
using StvkStress = Matrix2 (*)(const Matrix2& E, const Lame& lame);
/// Ex 9.2: the element's nodal forces [N] (columns), −V F S Dm⁻ᵀ on nodes 1 and 2, their
/// opposite sum on node 0, with E and S computed from F.
using StvkForces = ElementForces (*)(const Matrix32& F, const Matrix2& rest_inverse, double rest_volume,
                                     const Lame& lame);
/// Ex 9.3: ∂f/∂x [N/m], the 9×9 derivative of those forces by the nodes' positions.
using StvkStiffness = Matrix9 (*)(const Matrix32& F, const Matrix2& rest_inverse, double rest_volume,
                                  const Lame& lame);

/// The student's element, as the kit calls it.
struct FemKernels {
  DeformationGradient deformation_gradient = nullptr;  ///< ex 9.1
  GreenStrain green_strain = nullptr;                  ///< ex 9.1
  StvkStress stress = nullptr;                         ///< ex 9.2
  StvkForces forces = nullptr;                         ///< ex 9.2
  StvkStiffness stiffness = nullptr;                   ///< ex 9.3
};

/// The linear (small-strain) model of a plate in its plane: the Cauchy strain ε = ½(G + Gᵀ) − I
/// of the in-plane block G (the top 2×2 of F). Zero for a translation, not for a rotation: a turn
/// by θ reads as the strain (cos θ − 1) I.
Matrix2 cauchy_strain(const Matrix32& F);
/// Hooke's law in Lamé's form, σ = λ tr(ε) I + 2μ ε [Pa], for the small strain ε.
Matrix2 linear_stress(const Matrix2& strain, const Lame& lame);
/// Its forces: σ = λ tr(ε) I + 2μ ε, −V [σ; 0] Dm⁻ᵀ on nodes 1 and 2, the opposite sum on node 0.
ElementForces linear_forces(const Matrix32& F, const Matrix2& rest_inverse, double rest_volume,
                            const Lame& lame);
/// Its stiffness, the same at every F: ∂f/∂x of linear_forces, zero in z.
Matrix9 linear_stiffness(const Matrix2& rest_inverse, double rest_volume, const Lame& lame);

}  // namespace kit
