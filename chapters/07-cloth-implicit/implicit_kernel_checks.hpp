#pragma once
// The student's implicit kernels checked against computations of the kit's own (lecture, "Schéma
// implicite"): ex 7.1's spring stiffness block against central differences of Hooke's force, ex
// 7.2's assembly against the kit's pattern scatter, ex 7.3's PCG on a system the clamp was left
// off. The chapter prints what they find (say_*); the graded tests, not these, judge.
#include <string>

#include <kit/app/report.hpp>
#include <kit/cloth/cloth_run.hpp>

namespace kit {

/// Ex 7.1 on random springs (lengths 0.5–2 times rest, K 1–1e4 N/m), from a fixed seed.
struct JacobianCheck {
  int springs = 0;
  double finite_difference = 0;  ///< max ‖J − ∂f/∂x (central differences)‖ / ‖J‖, unclamped, all springs
  double asymmetry = 0;         ///< max ‖J − Jᵀ‖ / ‖J‖
  double clamped_lowest = 0;    ///< min eigenvalue of −J over compressed springs, clamped (≥ 0: definite)
  double unclamped_lowest = 0;  ///< the same without the clamp (< 0: indefinite), in units of K
};
JacobianCheck check_stiffness_block(SpringStiffnessBlock block, int springs = 1000);

/// Ex 7.2 against the kit's pattern scatter on the scene's sheet in a disturbed state, and the
/// clamp's effect on a compressed sheet.
struct AssemblyCheck {
  long rows = 0, nonzeros = 0;
  double matrix_difference = 0;    ///< max |A_ex − A_kit| / max |A_kit|
  double rhs_difference = 0;       ///< max |b_ex − b_kit| / max |b_kit|
  double asymmetry = 0;            ///< max |A − Aᵀ| / max |A|
  bool definite = false;           ///< a sparse Cholesky (LLT) of the clamped A succeeds
  bool unclamped_definite = true;  ///< the same on the compressed sheet without the clamp
  PcgResult unclamped_solve;       ///< ex 7.3 on that indefinite system (negative curvature expected)
  double triplet_seconds = 0;      ///< ex 7.2's assembly, per call [s]
  double scatter_seconds = 0;      ///< the kit's pattern scatter, per call [s]
};
AssemblyCheck check_assembly(const ClothScene& scene, const Springs& springs, ImplicitKernels kernels,
                             double h);

/// Section 1's sentence: what ex 7.1's block is against central differences, and the clamp's effect.
void say_jacobian_check(Report& report, const JacobianCheck& check);
/// Section 2's sentence: ex 7.2 against the scatter on `scene` at step h [s], and ex 7.3 unclamped.
void say_assembly_check(Report& report, const AssemblyCheck& check, const std::string& scene, double h);

}  // namespace kit
