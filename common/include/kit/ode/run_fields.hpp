#pragma once
// An adaptive run's outcome (adaptive_run.hpp) as report fields (report.hpp), under the same
// names in every chapter: status, message, rhs_evals (or the caller's key), accepted and
// rejected steps, and, given the reference y(T), error = max_i |y_i(T) − reference_i|.
#include <string>
#include <vector>

#include <kit/app/report.hpp>
#include <kit/ode/adaptive_run.hpp>

namespace kit {

template <class State>
std::vector<Field> run_fields(const AdaptiveRun<State>& run,
                              const std::string& evaluations_key = "rhs_evals") {
  return {{"status", std::string(name(run.status))},
          {"message", run.message},
          {evaluations_key, run.stats.rhs_evals},
          {"accepted", run.stats.steps},
          {"rejected", run.stats.rejected}};
}

template <class State>
std::vector<Field> run_fields(const AdaptiveRun<State>& run, const State& reference,
                              const std::string& evaluations_key = "rhs_evals") {
  std::vector<Field> fields = run_fields(run, evaluations_key);
  fields.push_back({"error", (run.accepted.u.back() - reference).cwiseAbs().maxCoeff()});
  return fields;
}

}  // namespace kit
