#pragma once
// Work against precision: the one harness that chapter 4 and `./kit bench adaptive` measure
// with. For each method it records a curve of points (tolerance, error reached at T, RHS
// evaluations, accepted and rejected steps, seconds), every point measured the same way on the
// same problem in the same process. Tolerances mean different things across libraries (GSL
// and Boost.Odeint use a max norm with a derivative term), so methods are compared by error
// reached against work, not by tolerance (ANCHORS.md, "Same problem, same tolerances").
//   methods (label, tolerances, run(tol) → WorkRun) + reference y(T)
//     → measure_work_precision → one WorkCurve per method.
// Timing: every (method, tolerance) run takes its turn in each round, in a rotating order, so
// that all meet the same disturbances from the rest of the machine; a point's time is its
// fastest round. Tests compare the counts, never the times.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <kit/base/state.hpp>

namespace kit {

/// What one run of a method at one tolerance returns.
template <int N>
struct WorkRun {
  Vec<N> y;                      ///< the state reached at T, units of y
  long rhs_evals = 0;            ///< evaluations of f(t, y)
  std::optional<long> accepted;  ///< accepted steps; empty when the method does not say
  std::optional<long> rejected;  ///< rejected steps; empty when the method does not say
  bool finished = true;          ///< false: stopped before T (step budget, step too small), so y ≠ y(T)
};

/// A method under measurement: run(tolerance) integrates the problem to T.
template <int N>
struct WorkMethod {
  std::string label;               ///< table row and legend entry, e.g. "GSL rkck"
  std::string look;                ///< gnuplot style of its curve (look.hpp plus a point type)
  std::vector<double> tolerances;  ///< rtol = atol of each run; for a fixed-step method, its step counts
  std::function<WorkRun<N>(double)> run;
};

/// One measured point of a curve.
struct WorkPoint {
  double tolerance = 0;          ///< as in WorkMethod::tolerances
  double error = 0;              ///< max_i |y_i(T) − reference_i|, units of y
  long rhs_evals = 0;            ///< evaluations of f
  std::optional<long> accepted;  ///< accepted steps, when the method says
  std::optional<long> rejected;  ///< rejected steps, when the method says
  bool finished = true;          ///< false: the run stopped before T, so `error` is not an error at T
  double seconds = 0;            ///< wall time of one run [s], the fastest of the rounds
  /// accepted + rejected, when both are known.
  std::optional<long> attempts() const;
};

/// One method's points, in the order of its tolerances.
struct WorkCurve {
  std::string label, look;
  std::vector<WorkPoint> points;
  std::vector<double> evaluations() const;  ///< rhs_evals of each point
  std::vector<double> errors() const;       ///< error of each point
  std::vector<double> seconds() const;      ///< seconds of each point
  /// Evaluations needed to reach `error`, interpolated on the curve (kit::cost_to_reach); NaN
  /// when the curve never gets that low.
  double evaluations_to_reach(double error) const;
};

/// How runs are timed. A sample repeats one run until `min_seconds` have passed (so that short
/// runs are not lost in the clock's resolution) and divides; a point keeps its fastest sample
/// over `rounds` rounds. Chapter 4: a few rounds of ≥ 1 ms; the bench: 301 single calls.
struct WorkTiming {
  int rounds = 3;             ///< rounds; every run takes one turn per round
  double min_seconds = 1e-3;  ///< least time per sample [s]; 0: one call per sample
};

/// Seconds per call of each of `runs`, timed as WorkTiming says: round after round, each run in
/// turn, the first run of round r being runs[r mod K]; the fastest sample of each run.
std::vector<double> fastest_interleaved(const std::vector<std::function<void()>>& runs,
                                        const WorkTiming& timing);

/// The point of `run` at `tolerance` against the reference y(T).
template <int N>
WorkPoint work_point(double tolerance, const WorkRun<N>& run, const Vec<N>& reference, double seconds) {
  return {tolerance,     (run.y - reference).cwiseAbs().maxCoeff(),
          run.rhs_evals, run.accepted,
          run.rejected,  run.finished,
          seconds};
}

/// Every method at each of its tolerances, counted against `reference` = y(T) and timed
/// interleaved (WorkTiming). Returns one curve per method, in order.
template <int N>
std::vector<WorkCurve> measure_work_precision(const std::vector<WorkMethod<N>>& methods,
                                              const Vec<N>& reference, const WorkTiming& timing = {}) {
  std::size_t total = 0;
  for (const auto& m : methods) total += m.tolerances.size();
  std::vector<WorkRun<N>> runs(total);  // one per (method, tolerance), in order
  std::vector<std::function<void()>> jobs;
  for (const auto& m : methods)
    for (double tolerance : m.tolerances)
      jobs.push_back([&m, tolerance, &slot = runs[jobs.size()]] { slot = m.run(tolerance); });
  const std::vector<double> seconds = fastest_interleaved(jobs, timing);
  std::vector<WorkCurve> curves;
  std::size_t i = 0;
  for (const auto& m : methods) {
    WorkCurve& curve = curves.emplace_back(WorkCurve{m.label, m.look, {}});
    for (double tolerance : m.tolerances) {
      curve.points.push_back(work_point(tolerance, runs[i], reference, seconds[i]));
      ++i;
    }
  }
  return curves;
}

}  // namespace kit
