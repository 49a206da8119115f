#pragma once
// The number of steps of the run a user asks for with --t-end and --dt: a usage error (exit 2)
// when T/Δt is not a whole number or the run would be too long to record.
#include <kit/fixed_steps.hpp>

namespace kit {

/// n = T/Δt for t_end = T [s] and dt = Δt [s], the steps a chapter records over [0, T].
/// Throws UsageError naming --t-end and --dt, their values and the allowed range when T/Δt is
/// not a whole number (to 1e-9 relative, see whole_steps) or n is outside [1, max_steps].
long require_whole_steps(double t_end, double dt, long max_steps);

}  // namespace kit
