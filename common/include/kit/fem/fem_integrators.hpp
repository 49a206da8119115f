#pragma once
// Chapter 9's time steps of the sheet: symplectic Euler and its stable step, and implicit Euler
// solved by chapter 7's filtered PCG (ex 7.3).
#include <kit/fem/fem_body.hpp>

namespace kit {

/// One step of symplectic Euler [s], with a drag −m c v of c [1/s]: v += h M⁻¹ f (filtered), x += h v.
void explicit_step(FemBody& body, double h, double drag);
/// A stable explicit step for the body in its present state [s]: 2/ω with ω² Gershgorin's bound
/// on the eigenvalues of M⁻¹K over the free coordinates (the largest row sum of |K_ij| / m_i).
/// The bound is above ω_max², so the step is below the true limit, by less than about two on
/// these meshes. Infinite for a body with no stiffness on its free coordinates.
double explicit_step_limit(const FemBody& body);

/// One step of implicit Euler [s] (Baraff & Witkin 1998, chapter 7's form):
///   (M (1 + h c) − h² K) Δv = h (f + h K v),   v += Δv,   x += h v,
/// solved by the filtered PCG (ex 7.3) to `tolerance`. Reports the solver's iterations and
/// whether it converged (it may not, if K is indefinite: a compressed St Venant–Kirchhoff element).
struct ImplicitStep {
  int iterations = 0;
  bool converged = false;
};
ImplicitStep implicit_step(FemBody& body, double h, double drag, double tolerance = 1e-8,
                           int max_iterations = 20000);

}  // namespace kit
