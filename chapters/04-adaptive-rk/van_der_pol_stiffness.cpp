#include "van_der_pol_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include <kit/app/progress.hpp>
#include <kit/ode/run_fields.hpp>

namespace kit {

namespace {
double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}
}  // namespace

StiffnessRun van_der_pol_stiffness(double mu, const Dopri5Runner& dopri5, long budget) {
  StiffnessRun out;
  out.mu = mu;
  out.budget = budget;
  // The relaxation period (3 − 2 ln 2)·μ for large μ; the harmonic 2π for small μ.
  out.two_periods = std::max(2 * (3 - 2 * std::log(2.0)) * mu, 4 * M_PI);
  out.predicted_steps = 4 * (std::log(2.0) + 0.75) * mu * mu / dopri5_real_stability_boundary;
  out.run = dopri5(VanDerPol{mu}, VanDerPol::initial_state(), out.two_periods, budget);
  out.horizon = out.run.accepted.t.back();
  out.adapted = out.run.status == RunStatus::too_many_steps;
  std::vector<double> h_lambda;
  for (std::size_t i = 0; i < out.run.step_sizes.size(); ++i) {
    const double x = out.run.accepted.u[i][0];
    if (std::abs(x) > 1.2) h_lambda.push_back(out.run.step_sizes[i] * mu * (x * x - 1));
  }
  out.median_step = median(out.run.step_sizes);
  out.median_h_lambda = median(h_lambda);
  out.stability_bound = std::abs(out.median_h_lambda / dopri5_real_stability_boundary - 1) < 0.15;
  return out;
}

RunEstimate van_der_pol_estimate(double mu, const Dopri5Runner& dopri5, long budget) {
  const double predicted = 4 * (std::log(2.0) + 0.75) * mu * mu / dopri5_real_stability_boundary;
  const double steps = std::min(predicted, static_cast<double>(budget));
  // The calibration: a short stretch (2000 steps) of the same run.
  const auto run = [&](long) { return dopri5(VanDerPol{mu}, VanDerPol::initial_state(), 1e9, 2000); };
  return {steps, seconds_per_step(run, 2000), 48 * steps};
}

StiffnessRun van_der_pol_stiffness(Report& report, double mu, const Dopri5Runner& dopri5, long budget) {
  const ProgressTask progress("stiffness (Van der Pol)");
  announce_run(report, "van_der_pol", "Van der Pol's run", van_der_pol_estimate(mu, dopri5, budget),
               fmt::format("--mu {}", mu));
  return van_der_pol_stiffness(mu, dopri5, budget);
}

std::vector<Field> report_fields(const StiffnessRun& s) {
  std::vector<Field> fields = run_fields(s.run);
  fields.insert(fields.end(),
                {{"mu", s.mu},
                 {"horizon", s.horizon},
                 {"two_periods", s.two_periods},
                 {"adapted", s.adapted},
                 {"budget", s.budget},
                 {"predicted_steps", s.predicted_steps},
                 {"median_step", s.median_step},
                 {"median_h_lambda", s.median_h_lambda},
                 {"boundary", dopri5_real_stability_boundary},
                 {"stability_bound", s.stability_bound},
                 {"verdict", std::string(s.stability_bound ? "stability, not accuracy, sets the step"
                                                           : "below it, so accuracy still sets the step")}});
  return fields;
}

}  // namespace kit
