#pragma once
// The judge's step_doubling.hpp (ex 4.1): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <utility>

#include <kit/ode/adaptive_run.hpp>

#include "remote/fields/adaptive_run.hpp"
#include "remote/judge.hpp"

namespace kit {

/// As in exercises/step_doubling.hpp, member for member (the student's program reads it so).
struct StepDoubling {
  double e_min = 1e-8;
  double e_max = 1e-6;
  double dt0 = 1e-3;
  double dt_min = 1e-12;
  int max_retries = 200;
  long max_steps = 10'000'000;
  bool guarded = true;
};
inline auto fields(StepDoubling& o) {
  return std::tie(o.e_min, o.e_max, o.dt0, o.dt_min, o.max_retries, o.max_steps, o.guarded);
}

template <class Step, class State>
AdaptiveRun<State> step_doubling(Step&& step, double t0, State u, double t_end, const StepDoubling& options) {
  return remote::call<AdaptiveRun<State>>("step_doubling/" + remote::key<State>(),
                                          remote::callback<State(double, const State&, double)>(step), t0, u,
                                          t_end, options);
}

}  // namespace kit
