#pragma once
// Chapter 1's report, its words apart from main.cpp's sections: the fall's sentence and the
// columns of each table (the samples of every run against the exact parabola, the cost of
// accuracy, where round-off wins).
#include <vector>

#include <kit/app/report.hpp>
#include <kit/problems/free_fall.hpp>

namespace kit {

/// Section 1's sentences: the fall, the step and the number of steps, and the sign of an error.
inline void say_free_fall(Report& report, const FreeFall& fall, double dt, long steps) {
  report.say("parameters", "Free fall: x0 = {x0} m, v0 = {v0} m/s, g = {g} m/s^2 (y axis up), dt = {dt} s, ",
             {{"x0", fall.x0}, {"v0", fall.v0}, {"g", fall.g}, {"dt", dt}});
  report.say("", "{steps} steps\nerr = x_method - x_exact; positive = above the exact parabola\n\n",
             {{"steps", steps}});
}

/// Section 2: about ten steps k of each run, its error and the predicted k/2·Δt²·|g| [m].
inline std::vector<Column> sample_columns() {
  return {{"k", "k"},
          {"t [s]", "t", "{:.4f}"},
          {"exact x [m]", "exact", "{:.6f}"},
          {"explicit x", "explicit", "{:.6f}"},
          {"implicit x", "implicit", "{:.6f}"},
          {"explicit err", "explicit_error", "{:.4e}"},
          {"implicit err", "implicit_error", "{:.4e}"},
          {"k/2·Δt²·|g|", "predicted_error", "{:.4e}"},
          {"match", "match", "check"},
          {"", "explicit_loop"},
          {"", "reference"}};
}

/// Section 4: explicit Euler's runs in double, each step size's work, error and time.
inline std::vector<Column> cost_columns() {
  return {{"Δt [s]", "dt", "{:.1e}"},        {"steps", "steps"},
          {"RHS evals", "rhs_evals"},        {"|error| [m]", "error", "{:.2e}"},
          {"time [s]", "seconds", "{:.1e}"}, {"ns/step", "ns_per_step", "{:.2f}"}};
}

/// Section 4: each round-off curve's best step and its smallest.
inline std::vector<Column> roundoff_columns() {
  return {{"curve", ""},
          {"best Δt [s]", "best_dt", "{:.3g}"},
          {"|error| [m]", "best_error", "{:.3g}"},
          {"smallest Δt [s]", "smallest_dt", "{:.3g}"},
          {"|error| there [m]", "smallest_dt_error", "{:.3g}"}};
}

}  // namespace kit
