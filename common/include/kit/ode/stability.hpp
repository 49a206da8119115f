#pragma once
// Linear stability, computed rather than guessed (lecture, "Précision/Stabilité"):
//  - the analytic side: spectral radius of a scheme's amplification on the damped oscillator
//    y'' + 2ζω y' + ω² y = 0, as a function of h = ωΔt and ζ;
//  - the measured side: does a simulation's amplitude grow over a long horizon?
//  - the critical step where the two change from stable to unstable, by bisection.
#include <array>
#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <vector>

#include <kit/app/progress.hpp>
#include <kit/base/state.hpp>

namespace kit {

/// max |eigenvalue| of a 2×2 matrix.
double spectral_radius(const Mat2& m);

/// The matrix M of a linear one-step map u → M u: its columns are the images of (1, 0) and
/// (0, 1). `step` must be the scheme applied to a homogeneous system (b = 0).
template <class Step>
Mat2 step_matrix(Step&& step) {
  Mat2 m;
  m.col(0) = step(Vec2(1.0, 0.0));
  m.col(1) = step(Vec2(0.0, 1.0));
  return m;
}

/// The eigenvalues of the oscillator y'' + 2ζω y' + ω² y = 0 times Δt, as z = λΔt, for
/// h = ωΔt: z = h (−ζ ± sqrt(ζ² − 1)).
std::pair<std::complex<double>, std::complex<double>> oscillator_z(double h, double zeta);

/// Spectral radius of a Runge–Kutta-type scheme on the oscillator: max |R(z)| over both z.
/// `amplification(z)` is the scheme's R.
double spectral_radius(const std::function<std::complex<double>(std::complex<double>)>& amplification,
                       double h, double zeta);

/// The smallest h in [0.01, h_max] where `radius(h)` exceeds 1 (+1e-13 for round-off): the
/// stability limit in ωΔt. Returns 0 when already unstable at h = 0.01 (read: unstable for
/// every Δt), and +∞ when stable up to h_max. Scans `samples` points on a log scale, then
/// bisects to `rel_tol`.
double stability_limit(const std::function<double(double)>& radius, double h_max, int samples = 2000,
                       double rel_tol = 1e-10);

/// Whether a linear simulation blows up: the largest |u − u_eq| over the last quarter of
/// `steps` steps exceeds twice that over the first quarter, or a state stops being finite.
/// A stable or neutral (bounded) motion stays below.
template <class Step>
bool grows(Step&& step, Vec2 u, const Vec2& equilibrium, long steps) {
  double early = 0, late = 0;
  for (long k = 0; k < steps; ++k) {
    u = step(u);
    const double size = (u - equilibrium).norm();
    if (!std::isfinite(size)) return true;
    if (k < steps / 4) early = std::max(early, size);
    if (k >= steps - steps / 4) late = std::max(late, size);
    if ((k + 1) % progress_chunk == 0) progress_add(static_cast<double>(progress_chunk));
  }
  return late > 2.0 * early;
}

/// The critical step between `stable_dt` (not unstable) and `unstable_dt` (unstable), by
/// bisection to `rel_tol` on `unstable(dt)`.
double critical_step(const std::function<bool(double)>& unstable, double stable_dt, double unstable_dt,
                     double rel_tol = 1e-6);

/// Points (x, y) on the grid [x0, x1] × [y0, y1] (nx × ny cells) where f(x, y) − level changes
/// sign along a cell edge, placed by linear interpolation: a level set drawn as dots.
std::vector<std::array<double, 2>> level_set_points(const std::function<double(double, double)>& f,
                                                    double level, double x0, double x1, double y0, double y1,
                                                    int nx, int ny);

}  // namespace kit
