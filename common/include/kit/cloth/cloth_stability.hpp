#pragma once
// How large a step an explicit cloth takes (ANCHORS, "Spring and explicit stability"): the
// prediction from the stiffest mode, ω_max² = the largest eigenvalue of M⁻¹K at rest (power
// iteration), and the largest Δt measured by bisection on runs that grow or stay bounded.
#include <cstdint>
#include <string>
#include <vector>

#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_scene.hpp>
#include <kit/cloth/cloth_system.hpp>

namespace kit {

/// √(largest eigenvalue of M⁻¹K) [rad/s], with K the springs' stiffness at positions x at rest
/// (each spring contributes k x̂x̂ᵀ; at rest the transverse term (1 − L0/l) vanishes) and pinned
/// nodes held (their rows and columns removed). Power iteration in the M inner product, from a
/// fixed pseudo-random start, until the Rayleigh quotient changes by less than `tolerance`.
struct OmegaMax {
  double omega = 0;  ///< [rad/s]
  int iterations = 0;
};
OmegaMax omega_max(const Springs& springs, const Eigen::VectorXd& masses, const NodeArray& x,
                   const std::vector<std::int32_t>& pins, double tolerance = 1e-9,
                   int max_iterations = 20000);

/// The largest Δt [s] for which every mode of the linearised cloth with frequencies in
/// (0, ω_max] and damping along the springs in proportion to stiffness (μ = c·k for every
/// family, c [s]) keeps a bounded amplitude, from each integrator's amplification of
///   x'' = −ω² x − c ω² x'.
/// Undamped (c = 0): symplectic Euler 2/ω_max, RK4 2√2/ω_max, explicit Euler and midpoint none
/// (0: they grow at every Δt). With c > 0 explicit Euler needs Δt < c for the underdamped modes
/// (ANCHORS: "stable iff Δt < μ/K") and Δt < 2/|λ| for the overdamped ones, λ the faster real
/// root of λ² + cω²λ + ω² = 0 (about 2/(cω²) when cω ≫ 2).
double predicted_dt_max(ClothIntegrator integrator, double omega_max, double damping_time = 0);

/// A measured Δt_max: the bisection's last stable and first unstable steps.
struct MeasuredDtMax {
  double stable = 0, unstable = 0;  ///< [s]; stable = 0 when even the smallest step tried grew
  int runs = 0;                     ///< runs made
  long steps = 0;                   ///< steps taken over all runs
  double estimate() const { return stable > 0 ? 0.5 * (stable + unstable) : 0.0; }
};
/// Bisects Δt in [lo, hi] (lo assumed stable, hi unstable; both are checked) on `scene` (gravity
/// and contacts as the scene has them), each run starting from rest plus a random displacement
/// of 1e-6 of the grid step on every free node, and unstable when some node moves more than
/// 1e3 times that from rest within `steps` steps. `relative` is the bisection's stopping width.
MeasuredDtMax measure_dt_max(const ClothScene& scene, const Springs& springs, ClothKernels kernels,
                             ClothIntegrator integrator, double lo, double hi, long steps = 2000,
                             double relative = 0.005);

/// The scene's sheet, springs and pins alone: no gravity, drag, collider, strain limit or spring
/// damping, so that the only motion is the springs' (the linearisation the prediction is made on).
ClothScene springs_only(const ClothScene& scene);

/// Δt_max of one integrator on the scene's sheet at n nodes along its longer side
/// (at_longest_side), its springs damped with
/// μ = damping_time·K (undamped at 0): the prediction from ω_max at rest and the measurement, with the
/// spring-force evaluations one simulated second costs at 0.9 Δt_max (the explicit cost, ∝ N³ for a fixed
/// sheet).
struct StabilityAtResolution {
  int n = 0;
  long springs = 0;
  double omega_max = 0;  ///< [rad/s]
  double predicted = 0;  ///< [s]
  MeasuredDtMax measured;
  double spring_evaluations_per_second = 0;  ///< per simulated second at 0.9 × measured Δt_max
};
/// `steps` bounds each run of the bisection (a weak growth needs many steps to show).
StabilityAtResolution stability_at(const ClothScene& scene, int n, ClothKernels kernels,
                                   ClothIntegrator integrator, double damping_time = 0, long steps = 2000);

/// The stability table of chapter 6 on the scene's sheet at n nodes across, all springs at the
/// scene's structural stiffness: undamped, symplectic Euler and RK4 on three layouts
/// (structural; + shear; + shear + bend); then damped along the springs, μ = damping_time·k,
/// with all four integrators on the full layout. Explicit Euler and midpoint grow slowly just
/// above their damped limit (by 1 + ω²Δt(Δt − c) a step for Euler), so their runs are 10× longer.
struct StabilityCase {
  std::string layout;
  ClothIntegrator integrator;
  double damping_time = 0;  ///< [s]
  StabilityAtResolution result;
};
std::vector<StabilityCase> stability_cases(const ClothScene& scene, int n, ClothKernels kernels,
                                           double damping_time);

}  // namespace kit
