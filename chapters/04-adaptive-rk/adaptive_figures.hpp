#pragma once
// The figures of chapter 4's adaptive runs, each method in its one style (look.hpp):
//   orbit_figure        the orbit with each accepted step of one run (x against y);
//   step_size_figure    h against t along that run, rejected steps marked;
//   work_figure         error reached against evaluations or wall time, one curve per method;
//   stiffness_figure    Van der Pol's x(t) above DOPRI5's accepted and rejected steps.
#include <string>
#include <vector>

#include <kit/app/figure.hpp>
#include <kit/ode/adaptive_run.hpp>
#include <kit/ode/work_precision.hpp>
#include <kit/problems/orbit_problem.hpp>

#include "van_der_pol_stiffness.hpp"

namespace kit {

/// The path of `problem` (GSL rk8pd at 1e-14) under the accepted steps of `run`, which `method`
/// took at (rtol, atol) and which `look` styles; Earth and Moon when the problem has them.
Figure orbit_figure(const OrbitProblem& problem, const AdaptiveRun<Vec4>& run, const std::string& method,
                    const std::string& look, double rtol, double atol);
/// h [time units] against t along `run` on a log scale; each rejected step a cross at (t, h tried).
Figure step_size_figure(const OrbitProblem& problem, const AdaptiveRun<Vec4>& run, const std::string& method,
                        const std::string& look);
/// max |y(T) − reference| against evaluations (by_time = false, "work-precision") or wall time [s]
/// ("work-precision-timing"), log-log. Errors below 1e-16 are drawn at 1e-16.
Figure work_figure(const std::vector<WorkCurve>& curves, const OrbitProblem& problem, bool by_time);
/// x(t) above h(t) of DOPRI5 on Van der Pol; beyond 20 000 accepted steps every k-th is drawn,
/// and the legend says so.
Figure stiffness_figure(const StiffnessRun& stiffness);

}  // namespace kit
