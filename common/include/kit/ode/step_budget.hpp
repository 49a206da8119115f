#pragma once
// A sweep over the time step Δt = T/m, m a whole number of steps, that stays within a budget
// of steps. Chapter 1 shrinks Δt until round-off wins (ERRATA item 2's error against Δt, pushed
// to the extreme); its finest run takes T/Δt_min steps, so a long horizon T would otherwise make
// it arbitrarily slow. Within the budget the sweep runs as asked; beyond it, its smallest step
// is raised, and the chapter says so.
#include <vector>

#include <kit/app/report.hpp>
#include <kit/app/run_estimate.hpp>

namespace kit {

/// The Δt range of a sweep over [0, T]. Every run covers [0, T] in m whole steps of Δt = T/m.
struct StepSweep {
  double t_end = 0;             ///< T [s], the horizon of every run
  double dt_max = 0;            ///< the largest step [s]: the coarsest run
  double dt_min_requested = 0;  ///< the smallest step asked for [s]
  double dt_min = 0;            ///< the smallest step used [s]: the one asked for, raised to
                                ///< T/max_steps when that is larger
  long max_steps = 0;           ///< the budget: no run of the sweep takes more steps

  /// True when the budget raised the smallest step above the one asked for.
  bool raised() const { return dt_min > dt_min_requested; }
  /// Steps of the coarsest run: T/dt_max rounded, at least 1.
  long fewest_steps() const;
  /// Steps of the finest run: T/dt_min rounded, at most max_steps and at least fewest_steps().
  long most_steps() const;
  /// The step counts m of the sweep, fewest to most, `per_decade` a decade on a log scale.
  std::vector<long> counts(int per_decade) const;
};

/// The sweep from dt_max down to dt_min [s] over [0, t_end], within max_steps steps a run:
/// dt_min is raised to t_end/max_steps when it asks for more. Needs t_end > 0,
/// 0 < dt_min <= dt_max and max_steps >= 1 (std::invalid_argument otherwise).
StepSweep budget_sweep(double t_end, double dt_max, double dt_min, long max_steps);

/// What a step of each of the round-off sweep's kernels costs [s], from calibration runs; 0 for
/// a kernel that does not run (a student's exercise not written yet).
struct RoundoffCosts {
  double explicit_double = 0;  ///< explicit Euler in double
  double explicit_float = 0;   ///< explicit Euler in float
  double implicit_float = 0;   ///< implicit Euler in float, matrix form (several times the others)
};
/// While the sweep runs, the weight of an implicit float step on the progress line, whose unit
/// is an explicit double step: set by announce_roundoff, read by the sweep (ProgressWeight).
inline double roundoff_implicit_weight = 1.0;

/// What chapter 1's round-off sweep costs: every count of `doubles` (4 a decade) once in double,
/// and those within `floats`' budget twice more (explicit and implicit Euler in float), each step
/// at its kernel's cost; it keeps a few numbers per run. `work` counts explicit double steps.
RunEstimate roundoff_estimate(const StepSweep& doubles, const StepSweep& floats, const RoundoffCosts& costs);
/// Announces that estimate (run_estimate.hpp) under "roundoff", naming --t-end and --dt-min, and
/// refuses a sweep that cannot fit (the step budget keeps every sweep far within the limits).
/// Sets roundoff_implicit_weight.
void announce_roundoff(Report& report, const StepSweep& doubles, const StepSweep& floats,
                       const RoundoffCosts& costs);

}  // namespace kit
