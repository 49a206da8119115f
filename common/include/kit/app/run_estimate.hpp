#pragma once
// What a run will cost, said before it starts: "This run takes about 2.3e9 steps: about 4 s
// and under 1 MB." An estimate comes from counts (the steps a sweep will take, the states a run
// will keep) times a per-step cost, measured by a short calibration run of the same kernel or
// taken as a conservative constant; never from timing the run itself. A run that cannot fit,
// over max_seconds or max_bytes, is refused before it starts: a UsageError (exit 2) that names
// the flags, their values and the estimate.
//
// Each estimate is a file of its own named for what it prices: cloth/cloth_estimate.hpp and
// sprites/sprite_estimate.hpp for a model's runs, NN-name/*_estimate.hpp for a chapter's
// (chapters 7, 8, 9), ode/step_budget.hpp for chapter 1's round-off sweep; Van der Pol's, a
// calibration and one product, stays with its run (chapter 4's van_der_pol_stiffness.hpp).
#include <string>
#include <string_view>

#include <kit/app/report.hpp>
#include <kit/base/stopwatch.hpp>

namespace kit {

/// The cost of a run, from counts.
struct RunEstimate {
  double steps = 0;             ///< work units: steps of the method (the progress line's units)
  double seconds_per_step = 0;  ///< from a calibration run, or a conservative constant [s]
  double bytes = 0;             ///< peak memory of what the run keeps [B]
  double work = 0;              ///< the progress line's total, when its units are not steps
                                ///< (steps weighted by their cost, progress.hpp); 0: steps
  std::string unit = "steps";   ///< what `steps` counts, in the text ("frames" for an animation)
  double seconds() const { return steps * seconds_per_step; }
};

/// When an estimate is printed, and when the run is refused.
struct RunLimits {
  double announce_seconds = 3.0;  ///< print the estimate from this long on [s]
  double announce_bytes = 5e8;    ///< or from this much memory on [B]
  double max_seconds = 600.0;     ///< refuse beyond 10 minutes [s]
  double max_bytes = 4e9;         ///< or beyond 4 GB [B]
};

/// Physical memory of this machine [B] (sysconf), the bound on what a run may ask for, or less:
/// KIT_MEMORY_LIMIT (bytes, at least 1e6) lowers it, for a shared machine, and lets the tests
/// check a refusal on any machine. A malformed value is a UsageError naming the variable.
double machine_memory();

/// "40 MB", "2.1 GB", "under 1 MB": an amount of memory for a person to read.
std::string describe_bytes(double bytes);
/// "about 2.3e+09 steps: about 4 s and under 1 MB".
std::string describe(const RunEstimate& estimate);

/// True when the run is too long or too large for `limits`.
bool over_limits(const RunEstimate& estimate, const RunLimits& limits = {});

/// Before a run: stores the estimate under summary[section]["estimate"] (steps, seconds, bytes,
/// announced), prints "This run takes about …." when it is long or large, and sets the total of
/// the progress line (progress.hpp) to its steps. When it cannot fit, throws a UsageError:
/// "{what} ({flags}) takes about …, over the limit of 10 min and 4 GB", `flags` naming the
/// flags and their values ("--t-end 1e4 s, --dt-min 1e-12 s").
void announce_run(Report& report, std::string_view section, std::string_view what,
                  const RunEstimate& estimate, std::string_view flags, const RunLimits& limits = {});

/// Seconds per step of `run(n)`, a kernel that takes n steps, from a short calibration: the
/// fastest of `samples` samples, each n = `steps` steps repeated until `min_seconds` have passed
/// (time_per_call). The fastest, because a machine busy with other work slows a sample down
/// by whole time slices, which a few milliseconds cannot average out.
template <class Run>
double seconds_per_step(Run&& run, long steps = 1L << 18, double min_seconds = 1e-3, int samples = 5) {
  double fastest = 0;
  for (int i = 0; i < samples; ++i) {
    double seconds = 0;
    time_per_call([&] { return run(steps); }, seconds, min_seconds);
    if (i == 0 || seconds < fastest) fastest = seconds;
  }
  return fastest / static_cast<double>(steps);
}

}  // namespace kit
