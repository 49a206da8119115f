#pragma once
// What an adaptive integration did: where it stepped, what it rejected, what it cost, and how
// it ended. A failure is a reported status with a message, never an abort or a hang.
#include <string>
#include <vector>

#include <kit/base/enum_names.hpp>
#include <kit/base/state.hpp>

namespace kit {

enum class RunStatus {
  finished,        ///< reached t_end
  trapped,         ///< step doubling oscillated between halving and doubling (ERRATA item 10)
  step_too_small,  ///< the step fell below the smallest allowed (unreachable tolerance, or NaN/Inf)
  too_many_steps,  ///< the step budget ran out
  unreachable,     ///< the tolerance is below what double precision can deliver (rtol < 10 ε)
};
/// Each status's name in reports and summaries ("step too small").
inline constexpr auto run_status_names = enum_names<RunStatus>({
    {RunStatus::finished, "finished", "finished"},
    {RunStatus::trapped, "trapped", "trapped"},
    {RunStatus::step_too_small, "step too small", "step too small"},
    {RunStatus::too_many_steps, "too many steps", "too many steps"},
    {RunStatus::unreachable, "unreachable tolerance", "unreachable tolerance"},
});
static_assert(run_status_names.in_order());
inline const char* name(RunStatus status) { return run_status_names.flag(status); }

/// Empty when (rtol, atol) can be met in double precision; else why not. An error estimate
/// sees truncation only: below rtol = 10 ε, round-off in y wins whatever the step (the check of
/// Hairer's RADAU5), so such a tolerance is refused up front.
std::string unreachable_tolerance(double rtol, double atol);

template <class State>
struct AdaptiveRun {
  Trajectory<State> accepted;      ///< (t_n, y_n) at every accepted step, from t0
  std::vector<double> step_sizes;  ///< h of each accepted step [s]
  std::vector<double> rejected_t;  ///< where each rejected step started [s]
  std::vector<double> rejected_h;  ///< and the step it tried [s]
  Stats stats;                     ///< evaluations, accepted and rejected steps
  RunStatus status = RunStatus::finished;
  std::string message;  ///< empty when finished; else what happened, where, why
};

}  // namespace kit
