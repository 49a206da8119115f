#pragma once
// The number of steps of the run a user asks for with --t-end and --dt: a usage error (exit 2)
// when T/Δt is not a whole number or the run would be too long to record.
#include <kit/ode/fixed_steps.hpp>

namespace kit {

/// What recording one step keeps, for every method a chapter runs (time and state of each, the
/// reference's, the figures' data) [B]: the memory estimate of a refusal.
inline constexpr double recorded_step_bytes = 160;

/// n = T/Δt for t_end = T [s] and dt = Δt [s], the steps a chapter records over [0, T].
/// Throws UsageError naming --t-end and --dt, their values and the allowed range when T/Δt is
/// not a whole number (to 1e-9 relative, see whole_steps) or n is outside [1, max_steps]; past
/// max_steps the message gives the estimate of the memory the run would take
/// (`bytes_per_step` a step, run_estimate.hpp) beside that of the limit.
long require_whole_steps(double t_end, double dt, long max_steps,
                         double bytes_per_step = recorded_step_bytes);

}  // namespace kit
