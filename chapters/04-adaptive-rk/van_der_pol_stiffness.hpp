#pragma once
// What an explicit method does on a stiff problem: DOPRI5 on Van der Pol's
// oscillator (adaptive_rk_models.hpp) at large μ, where stability, not accuracy, holds the step
// down (Hairer & Wanner, Solving ODEs II, IV.1–2). On the slow branches the Jacobian's stiff
// eigenvalue is about λ = −μ(x² − 1); if stability sets the step, h·|λ| sits at DOPRI5's
// stability boundary on the negative real axis, 3.31 (ANCHORS.md).
//   μ, a DOPRI5, step budget → StiffnessRun (the run, median h, median h·|λ| on the slow
//   branches, verdict). The DOPRI5 is the caller's: the production one, or a student's.
#include <functional>
#include <vector>

#include <kit/app/report.hpp>
#include <kit/app/run_estimate.hpp>
#include <kit/base/state.hpp>
#include <kit/ode/adaptive_run.hpp>
#include <kit/problems/adaptive_rk_models.hpp>

namespace kit {

/// DOPRI5's stability boundary on the negative real axis: |R(z)| ≤ 1 for z ∈ [−3.31, 0].
inline constexpr double dopri5_real_stability_boundary = 3.31;

struct StiffnessRun {
  double mu = 0;           ///< Van der Pol's μ
  double two_periods = 0;  ///< the horizon asked for: twice max((3 − 2 ln 2)·μ, 2π), time units
  double horizon = 0;      ///< the horizon reached: two_periods, or less when the budget ran out
  bool adapted = false;    ///< true when the step budget ended the run before two_periods
  long budget = 0;         ///< DOPRI5's step budget (accepted + rejected)
  /// Steps two periods take when stability holds h·|λ| at the boundary b on the slow branches:
  /// 4 branches × (μ²/b)·∫₁² (x² − 1)²/x dx = 4·(ln 2 + 3/4)·μ²/b ≈ 1.74 μ².
  double predicted_steps = 0;
  AdaptiveRun<Vec2> run;       ///< from y0 = (2, 0), rtol = atol = 1e-6, HINIT's first step
  double median_step = 0;      ///< median accepted h, time units
  double median_h_lambda = 0;  ///< median of h·μ(x² − 1) over accepted steps with |x| > 1.2; NaN if none
  bool stability_bound = false;  ///< median_h_lambda within 15% of the stability boundary
};

/// A DOPRI5 run of Van der Pol from (t = 0, y0) to t_end at rtol = atol = 1e-6, within
/// `max_steps` steps (accepted + rejected).
using Dopri5Runner =
    std::function<AdaptiveRun<Vec2>(const VanDerPol& f, const Vec2& y0, double t_end, long max_steps)>;

/// `dopri5` on Van der Pol with `mu` over two periods, or over as much of them as `budget` steps
/// cover (a large μ is never refused: the run says how far it got).
StiffnessRun van_der_pol_stiffness(double mu, const Dopri5Runner& dopri5, long budget = 2'000'000);

/// What that run costs: min(predicted steps, budget) DOPRI5 steps at the cost of a step measured
/// on a short run of the same problem, and the trajectory it keeps (about 48 B a step).
RunEstimate van_der_pol_estimate(double mu, const Dopri5Runner& dopri5, long budget = 2'000'000);

/// The same run, its estimate announced first (run_estimate.hpp) under "van_der_pol", and its
/// steps counted on the progress line.
StiffnessRun van_der_pol_stiffness(Report& report, double mu, const Dopri5Runner& dopri5,
                                   long budget = 2'000'000);

/// Every value above as report fields (run_fields.hpp for the run), plus "boundary" = 3.31 and
/// "verdict", the sentence that says which of stability and accuracy sets the step.
std::vector<Field> report_fields(const StiffnessRun& stiffness);

}  // namespace kit
