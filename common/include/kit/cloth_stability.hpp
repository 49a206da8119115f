#pragma once
// How large a step an explicit cloth takes (ANCHORS, "Spring and explicit stability"): the
// prediction from the stiffest mode, ω_max² = the largest eigenvalue of M⁻¹K at rest (power
// iteration), and the largest Δt measured by bisection on runs that grow or stay bounded.
#include <cstdint>
#include <vector>

#include <kit/cloth.hpp>
#include <kit/cloth_scene.hpp>
#include <kit/cloth_system.hpp>

namespace kit {

/// √(largest eigenvalue of M⁻¹K) [rad/s], with K the springs' stiffness at positions x at rest
/// (each spring contributes k x̂x̂ᵀ; at rest the transverse term (1 − L0/l) vanishes) and pinned
/// nodes held (their rows and columns removed). Power iteration in the M inner product, from a
/// fixed pseudo-random start, until the Rayleigh quotient changes by less than `tolerance`.
struct OmegaMax {
  double omega = 0;   ///< [rad/s]
  int iterations = 0;
};
OmegaMax omega_max(const Springs& springs, const Eigen::VectorXd& masses, const NodeArray& x,
                   const std::vector<std::int32_t>& pins, double tolerance = 1e-9, int max_iterations = 20000);

/// The largest Δt [s] for which every mode of the linearised cloth with frequencies in
/// (0, ω_max] and damping along the springs in proportion to stiffness (μ = c·k for every
/// family, c [s]) keeps a bounded amplitude, from each integrator's amplification of
///   x'' = −ω² x − c ω² x'.
/// Undamped (c = 0): symplectic Euler 2/ω_max, RK4 2√2/ω_max, explicit Euler and midpoint none
/// (0: they grow at every Δt). With c > 0 explicit Euler needs Δt < c for the underdamped modes
/// and Δt < 2/(c ω²) for the overdamped ones (ANCHORS: "stable iff Δt < μ/K").
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

}  // namespace kit
