// Chapter 3: the midpoint Runge–Kutta method (lecture, "Monter en degré ?", "Runge Kutta").
// Taylor's higher derivatives are out of reach, but two evaluations of F per step buy a second
// order: u_{k+1/2} = u_k + Δt/2 F(u_k), u_{k+1} = u_k + Δt F(u_{k+1/2}). Exact on free fall,
// second order on the spring. The chapter fits every scheme's order, shows that symplectic
// Euler's energy error stays bounded, and prices accuracy in right-hand-side evaluations.
#include <cmath>
#include <map>
#include <vector>

#include <fmt/format.h>

#include <kit/app/chapter_app.hpp>
#include <kit/ode/convergence_sweep.hpp>
#include <kit/ode/energy_drift.hpp>
#include <kit/ode/fixed_steps.hpp>
#include <kit/problems/free_fall.hpp>
#include <kit/problems/spring.hpp>

#include "explicit_euler.hpp"
#include "midpoint.hpp"
#include "rk2_report.hpp"
#include "scheme_figures.hpp"
#include "spring_flags.hpp"
#include "spring_steppers.hpp"

namespace {
using kit::Scheme;
using kit::Vec2;
using Sweeps = std::map<Scheme, kit::ConvergenceSweep>;
using Drifts = std::map<Scheme, kit::EnergyDrift>;
const std::vector<double> targets{1e-3, 1e-6, 1e-9};  // errors at T [m] that section 4 prices

// 1. Free fall over 1 s: the midpoint step is exact (lecture: x^k = x0 + kΔt v0 + (kΔt)²/2 g).
void free_fall_is_exact(kit::Report& report, long steps) {
  const kit::FreeFall fall;
  const double dt = 1.0 / double(steps), exact = fall.position(double(steps) * dt);
  const auto off_by = [&](const char* method, auto step) {  // |x_N − x(1 s)| / |x(1 s)|, once written
    const auto error = [&] { return std::abs(kit::advance(fall.initial_state(), steps, step)[0] - exact); };
    return kit::optional_value(report.attempt(method, [&] { return error() / std::abs(exact); }));
  };
  const auto midpoint = off_by("free-fall midpoint", [&](auto& u) { return midpoint_step(fall, 0., u, dt); });
  const auto euler = off_by("free-fall Euler", [&](auto& u) { return explicit_euler_step(fall, 0., u, dt); });
  report.say("free_fall",
             "Free fall over 1 s in {steps} steps: midpoint RK2 is off by "
             "{midpoint_relative_error:.2e} (relative), explicit Euler by {euler_relative_error:.2e}.\n"
             "Midpoint RK2 integrates x'' = g exactly: what remains is round-off.\n\n",
             {{"steps", steps}, {"midpoint_relative_error", midpoint}, {"euler_relative_error", euler}});
}

// 2. Orders on the spring at T: least squares over ω·Δt ≤ min(0.05, (ω·T)^(-1/p)), above round-off
//    (error ≥ 1e-10 m). A T too long for the sweep is shortened, and the text and JSON say so.
Sweeps orders_on_the_spring(kit::ChapterApp& app, const kit::Spring& spring, const Vec2& u0, double t_end,
                            const kit::SweepHorizon& horizon, const std::vector<Scheme>& schemes) {
  const kit::ProgressTask progress("orders");  // the progress line on a terminal
  const double w = spring.omega();
  kit::say_spring_horizon(app.report(), spring, horizon, t_end);
  auto orders = app.report().table("orders", kit::order_columns());
  Sweeps sweeps;
  for (Scheme s : schemes) {
    const auto error_at = [&](long n) {
      const Vec2 u = kit::advance(u0, n, kit::spring_stepper(s, spring, horizon.t / double(n)));
      return std::abs(u[0] - kit::spring_motion(spring, u0, horizon.t)[0]);
    };
    const int p = kit::order(s), per_step = kit::evaluations_per_step(s);
    const auto& sweep = sweeps[s] = kit::sweep_convergence(error_at, horizon.t, w, p, per_step);
    orders.row(kit::key(s),
               {kit::name(s), long(p), sweep.order.slope, sweep.fitted, long(per_step), sweep.best_error()});
  }
  orders.print();
  return sweeps;
}

// 3. Energy over many periods: symplectic Euler's error oscillates but stays bounded.
Drifts energy_over_periods(kit::ChapterApp& app, const kit::Spring& spring, const Vec2& u0, long periods,
                           const std::vector<Scheme>& schemes) {
  const kit::ProgressTask progress("energy");
  const long steps = long(std::ceil(double(periods) * 2 * M_PI / 0.1));
  const double dt = 0.1 / spring.omega();
  app.report().say("energy_run",
                   "\nEnergy over {periods} periods with omega·dt = {omega_dt} "
                   "({steps} steps):\n",
                   {{"periods", periods}, {"omega_dt", 0.1}, {"steps", steps}});
  auto table = app.report().table("energy", kit::energy_columns());
  Drifts drifts;
  const auto energy = [&](const Vec2& u) { return spring.energy(u); };
  for (Scheme s : schemes) {
    const auto& d = drifts[s] = kit::energy_drift(u0, dt, steps, kit::spring_stepper(s, spring, dt), energy);
    table.row(kit::key(s), {kit::name(s), d.max_drift, d.final_ratio, kit::optional_value(d.diverged_at)});
  }
  table.print();
  return drifts;
}

// 4. What accuracy costs: right-hand-side evaluations to reach 1e-3, 1e-6 and 1e-9 m at T.
void what_accuracy_costs(kit::ChapterApp& app, const Sweeps& sweeps) {
  app.report().print("\nRight-hand-side evaluations needed for an error at T (implicit Euler: a linear "
                     "solve counts as one;\npast 1e9 steps round-off wins over truncation in double, "
                     "chapter 1):\n");
  auto cost = app.report().table("evaluations_needed", kit::evaluations_columns());
  for (const auto& [s, sweep] : sweeps) {
    for (double target : targets) {
      const auto n = kit::evaluations_needed(sweep, kit::evaluations_per_step(s), target);
      const kit::ReportValue measured = n.extrapolated ? kit::ReportValue{} : long(n.evaluations);
      const kit::ReportValue fitted = n.extrapolated ? kit::ReportValue{n.evaluations} : kit::ReportValue{};
      cost.row_at({kit::key(s), fmt::format("{:.0e}", target)},
                  {kit::name(s), target, measured, fitted, n.reachable, n.extrapolated ? fitted : measured,
                   n.extrapolated});
    }
  }
  cost.print();
}

// 5. The figures.
void figures(kit::ChapterApp& app, const Sweeps& sweeps, const Drifts& drifts, double t, long periods) {
  app.figure(kit::convergence_figure(sweeps, t));
  app.figure(kit::work_figure(sweeps, targets));
  app.figure(kit::energy_figure(drifts, periods));
}
}  // namespace

int main(int argc, char** argv) {
  kit::Spring spring;  // m = 1 kg, K = 100 N/m, μ = 0, L0 = 1 m
  Vec2 u0(1.5, 0.0);
  double t_end = 2.0;
  long free_fall_steps = 10'000, periods = 1000;
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 3: midpoint RK2, what order buys");
  kit::add_spring_flags(app, spring, u0, 1e9);
  app.add_real("--t-end", t_end, "time T at which errors are measured [s]", kit::positive(1e4));
  app.add_count("--free-fall-steps", free_fall_steps, "midpoint steps on free fall", 1, 10'000'000);
  app.add_count("--periods", periods, "length of the energy run, in periods of the spring", 1, 100'000);
  return app.run(argc, argv, [&] {
    kit::require_motion(spring, u0);
    const kit::SweepHorizon horizon = kit::sweep_horizon(spring.omega(), t_end);
    free_fall_is_exact(app.report(), free_fall_steps);  // every method runs once its exercise is written
    const auto schemes = kit::written_schemes(app.report(), spring, u0, 0.01 / spring.omega());
    const auto sweeps = orders_on_the_spring(app, spring, u0, t_end, horizon, schemes);
    const auto drifts = energy_over_periods(app, spring, u0, periods, schemes);
    what_accuracy_costs(app, sweeps);
    if (!app.options().no_plot) figures(app, sweeps, drifts, horizon.t, periods);
  });
}
