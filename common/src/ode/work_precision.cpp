#include <kit/ode/work_precision.hpp>

#include <algorithm>
#include <limits>

#include <kit/app/progress.hpp>
#include <kit/base/measure.hpp>
#include <kit/base/stopwatch.hpp>

namespace kit {

std::optional<long> WorkPoint::attempts() const {
  if (!accepted || !rejected) return std::nullopt;
  return *accepted + *rejected;
}

std::vector<double> WorkCurve::evaluations() const {
  std::vector<double> values;
  for (const WorkPoint& p : points) values.push_back(static_cast<double>(p.rhs_evals));
  return values;
}

std::vector<double> WorkCurve::errors() const {
  std::vector<double> values;
  for (const WorkPoint& p : points) values.push_back(p.error);
  return values;
}

std::vector<double> WorkCurve::seconds() const {
  std::vector<double> values;
  for (const WorkPoint& p : points) values.push_back(p.seconds);
  return values;
}

double WorkCurve::evaluations_to_reach(double error) const {
  return cost_to_reach(evaluations(), errors(), error);
}

std::vector<double> fastest_interleaved(const std::vector<std::function<void()>>& runs,
                                        const WorkTiming& timing) {
  std::vector<double> best(runs.size(), std::numeric_limits<double>::infinity());
  // The progress line counts seconds of timing: once the first round is done, all the rounds
  // are expected to take as long as it did each.
  const Stopwatch clock;
  for (int round = 0; round < timing.rounds; ++round) {
    for (std::size_t turn = 0; turn < runs.size(); ++turn) {
      const std::size_t i =
          (turn + static_cast<std::size_t>(round)) % runs.size();  // each follows each in turn
      const Stopwatch sample;
      double seconds = 0;
      {
        const ProgressWeight uncounted(0);  // the steps a run reports are not this task's seconds
        time_per_call(
            [&] {
              runs[i]();
              return 0;
            },
            seconds, timing.min_seconds);
      }
      best[i] = std::min(best[i], seconds);
      progress_add(sample.seconds());
    }
    if (round == 0) ProgressTask::set_total(clock.seconds() * timing.rounds);
  }
  return best;
}

}  // namespace kit
