#pragma once
// Chapter 3's report, its words apart from main.cpp's sections: the spring's sentence and the
// columns of each table (fitted orders, energy over many periods, evaluations for an accuracy).
#include <vector>

#include <kit/app/report.hpp>
#include <kit/ode/convergence_sweep.hpp>
#include <kit/problems/spring.hpp>

namespace kit {

/// Section 2's sentence: the spring and the time T [s] at which errors are measured, and why T
/// was shortened when it was (`t_end` as asked [s]).
inline void say_spring_horizon(Report& report, const Spring& spring, const SweepHorizon& horizon,
                               double t_end) {
  const double w = spring.omega();
  report.say("spring",
             "Spring: m = {mass} kg, K = {stiffness} N/m, mu = {damping} N·s/m, "
             "omega = {omega:.4g} rad/s; errors |x_N - x(T)| at T = {t:.4g} s\n",
             {{"mass", spring.mass},
              {"stiffness", spring.stiffness},
              {"damping", spring.damping},
              {"omega", w},
              {"t", horizon.t},
              {"adapted", horizon.adapted}});
  if (horizon.adapted)
    report.say("spring",
               "(--t-end {t_end} s gives omega·T = {omega_t:.3g}; a decade of omega·dt <= "
               "min(0.05, 1/(omega·T)) in 1e6 steps needs omega·T <= {omega_t_max:.3g}.)\n",
               {{"t_end", t_end}, {"omega_t", w * t_end}, {"omega_t_max", w * horizon.t}});
}

/// Section 2's table: each scheme's expected and fitted order, and its best error [m].
inline std::vector<Column> order_columns() {
  return {{"scheme", "scheme"},
          {"expected order", "expected"},
          {"fitted order", "fitted", "{:.3f}"},
          {"points fitted", "points"},
          {"evals/step", "evaluations_per_step"},
          {"best error [m]", "best_error", "{:.1e}"}};
}

/// Section 3's table: each scheme's energy drift over the run.
inline std::vector<Column> energy_columns() {
  return {{"scheme", "scheme"},
          {"max |E/E0 - 1|", "max_drift", "{:.2e}"},
          {"E/E0 at the end", "final_ratio", "{:.3e}"},
          {"diverged at t [s]", "diverged_at", "{:.4g}"}};
}

/// Section 4's table: the evaluations each scheme needs for an error at T, measured or extrapolated.
inline std::vector<Column> evaluations_columns() {
  return {{"scheme", "scheme"},
          {"error at T [m]", "target", "{:.0e}"},
          {"measured", "measured"},
          {"extrapolated", "extrapolation", "~{:.0e}"},
          {"within 1e9 steps", "reachable"},
          {"", "evaluations"},
          {"", "extrapolated"}};
}

}  // namespace kit
