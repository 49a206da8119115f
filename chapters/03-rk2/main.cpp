// Chapter 3: the midpoint Runge–Kutta method (lecture, "Monter en degré ?", "Runge Kutta").
// Taylor's higher derivatives are out of reach, but two evaluations of F per step buy a second
// order: u_{k+1/2} = u_k + Δt/2 F(u_k), u_{k+1} = u_k + Δt F(u_{k+1/2}). On free fall it is
// exact; on the spring it is second order. The chapter fits every scheme's order, shows that
// symplectic Euler's energy error stays bounded, and prices accuracy in right-hand-side
// evaluations.
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include <kit/chapter_app.hpp>
#include <kit/fixed_steps.hpp>
#include <kit/free_fall.hpp>
#include <kit/measure.hpp>
#include <kit/spring.hpp>
#include <kit/spring_flags.hpp>
#include <kit/table.hpp>

#include "explicit_euler.hpp"
#include "midpoint.hpp"
#include "spring_steppers.hpp"

namespace {
using kit::Scheme;
using kit::Vec2;

// |x_n − x(T)| after n steps of Δt = T/n of `scheme` on the spring, and the RHS evaluations spent.
struct Point {
  double dt, error;
  long evaluations;
};
Point spring_error(Scheme s, const kit::Spring& spring, const Vec2& u0, double t_end, long n) {
  const double dt = t_end / double(n);
  const Vec2 u = kit::advance(u0, n, kit::spring_stepper(s, spring, dt));
  return {dt, std::abs(u[0] - kit::spring_motion(spring, u0, t_end)[0]), n * kit::evaluations_per_step(s)};
}

// Evaluations needed to reach `tolerance`: the first measured point at or below it or, when
// none is, the extrapolation of `cost_fit` (error against evaluations) beyond the sweep. Past
// 1e9 steps it is "never": chapter 1 measured round-off overtaking truncation there in double.
std::string needed(const std::vector<Point>& points, const kit::LogLogFit& cost_fit, int evaluations_per_step, double tolerance,
                   nlohmann::json& json) {
  for (const Point& p : points) {
    if (p.error <= tolerance) {
      json = {{"evaluations", p.evaluations}, {"extrapolated", false}, {"reachable", true}};
      return fmt::format("{}", p.evaluations);
    }
  }
  const double extrapolated = std::pow(10.0, (std::log10(tolerance) - cost_fit.intercept) / cost_fit.slope);
  const bool reachable = extrapolated / evaluations_per_step <= 1e9;  // steps, not evaluations
  json = {{"evaluations", extrapolated}, {"extrapolated", true}, {"reachable", reachable}};
  return reachable ? fmt::format("~{:.0e} (extrapolated)", extrapolated) : fmt::format("never (~{:.0e}: round-off wins first)", extrapolated);
}
}  // namespace

int main(int argc, char** argv) {
  kit::Spring spring;  // m = 1 kg, K = 100 N/m, μ = 0, L0 = 1 m
  Vec2 u0(1.5, 0.0);
  double t_end = 2.0;
  long free_fall_steps = 10'000, periods = 1000;
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 3: the midpoint Runge-Kutta method and what order buys");
  kit::add_spring_flags(app, spring, u0, 1e9);
  app.add_real("--t-end", t_end, "time T at which errors are measured [s]", kit::positive(1e4));
  app.add_count("--free-fall-steps", free_fall_steps, "midpoint steps on free fall", 1, 10'000'000);
  app.add_count("--periods", periods, "length of the energy run, in periods of the spring", 1, 100'000);

  return app.run(argc, argv, [&] {
    kit::require_motion(spring, u0);
    // The order fit needs steps with ω·Δt ≤ 0.05 within the sweep's 10⁶ steps, over a decade.
    if (spring.omega() * t_end > 5000)
      throw kit::UsageError(fmt::format("--stiffness {} / --mass {} with --t-end {} gives omega·T = {:.3g}: expected at most 5000 "
                                        "(the order fit needs omega·dt <= 0.05 within 1e6 steps)", spring.stiffness, spring.mass,
                                        t_end, spring.omega() * t_end));
    auto& out = app.text();
    auto& json = app.summary();
    const double w = spring.omega();

    // 1. Free fall: the midpoint step is exact (lecture: x^k = x0 + kΔt v0 + (kΔt)²/2 g).
    const kit::FreeFall fall;
    const double dt_fall = 1.0 / double(free_fall_steps);  // over 1 s: x stays far from 0, so relative error means something
    const auto f = [&](double t, const Vec2& u) { return fall(t, u); };
    const Vec2 mid = kit::advance(fall.initial_state(), free_fall_steps, [&](const Vec2& u) { return kit::midpoint_step(f, 0.0, u, dt_fall); });
    const Vec2 eul = kit::advance(fall.initial_state(), free_fall_steps, [&](const Vec2& u) { return kit::explicit_euler_step(f, 0.0, u, dt_fall); });
    const double exact = fall.position(double(free_fall_steps) * dt_fall);
    const double relative = std::abs(mid[0] - exact) / std::abs(exact), euler_relative = std::abs(eul[0] - exact) / std::abs(exact);
    out << fmt::format("Free fall over 1 s in {} steps: midpoint RK2 is off by {:.2e} (relative), explicit Euler by {:.2e}.\n"
                       "Midpoint RK2 integrates x'' = g exactly: what remains is round-off.\n\n", free_fall_steps, relative, euler_relative);
    json["free_fall"] = {{"steps", free_fall_steps}, {"midpoint_relative_error", relative}, {"euler_relative_error", euler_relative}};

    // 2. Orders on the spring, at the fixed time T: least squares over the asymptotic range
    //    (ω·Δt ≤ 0.05) and above round-off (error ≥ 1e-10 m).
    out << fmt::format("Spring: m = {} kg, K = {} N/m, mu = {} N·s/m, omega = {:.4g} rad/s; errors |x_N - x(T)| at T = {} s\n",
                       spring.mass, spring.stiffness, spring.damping, w, t_end);
    kit::Table orders({"scheme", "expected order", "fitted order", "points fitted", "evals/step"});
    std::map<Scheme, std::vector<Point>> sweeps;
    std::map<Scheme, kit::LogLogFit> fits, cost_fits;
    for (Scheme s : kit::all_schemes) {
      kit::Sweep asymptotic, by_cost;  // error against Δt, and against evaluations
      for (long n : kit::geometric_counts(std::max(10L, long(std::ceil(w * t_end / 2))), 1'000'000, 8)) {
        const Point p = spring_error(s, spring, u0, t_end, n);
        sweeps[s].push_back(p);
        if (w * p.dt <= 0.05 && p.error >= 1e-10) asymptotic.add(p.dt, p.error), by_cost.add(double(p.evaluations), p.error);
      }
      fits[s] = kit::fit_loglog(asymptotic.dt, asymptotic.error);
      cost_fits[s] = kit::fit_loglog(by_cost.dt, by_cost.error);
      orders.add_row({kit::name(s), std::to_string(kit::order(s)), kit::fixed(fits[s].slope, 3), std::to_string(asymptotic.dt.size()),
                      std::to_string(kit::evaluations_per_step(s))});
      json["orders"][kit::key(s)] = {{"expected", kit::order(s)}, {"fitted", fits[s].slope}, {"points", asymptotic.dt.size()}};
    }
    orders.print(out);

    // 3. Energy over many periods: symplectic Euler's error oscillates but stays bounded.
    const double dt_energy = 0.1 / w, e0 = spring.energy(u0);
    const long energy_steps = long(std::ceil(periods * 2 * M_PI / 0.1));
    kit::Table drift({"scheme", "max |E/E0 - 1|", "E/E0 at the end"});
    std::map<Scheme, kit::Trajectory<Vec2>> energy_runs;
    for (Scheme s : kit::all_schemes) {
      const auto stepper = kit::spring_stepper(s, spring, dt_energy);
      kit::Trajectory<Vec2> run;
      Vec2 u = u0;
      double worst = 0;
      for (long k = 0;; ++k) {  // states u_0 .. u_N: N steps exactly
        worst = std::max(worst, std::abs(spring.energy(u) / e0 - 1));
        if (k % std::max(1L, energy_steps / 2000) == 0 || k == energy_steps) run.push(double(k) * dt_energy, u);
        if (k == energy_steps) break;
        u = stepper(u);
      }
      drift.add_row({kit::name(s), kit::sci(worst, 3), kit::sci(spring.energy(u) / e0, 4)});
      json["energy"][kit::key(s)] = {{"max_drift", worst}, {"final_ratio", spring.energy(u) / e0}};
      energy_runs.emplace(s, std::move(run));
    }
    out << fmt::format("\nEnergy over {} periods with omega·dt = 0.1 ({} steps):\n", periods, energy_steps);
    drift.print(out);

    // 4. What accuracy costs: right-hand-side evaluations to reach 1e-3, 1e-6 and 1e-9 m at T.
    kit::Table cost({"scheme", "for 1e-3 m", "for 1e-6 m", "for 1e-9 m", "best error [m]"});
    for (Scheme s : kit::all_schemes) {
      std::vector<std::string> row{kit::name(s)};
      for (double tolerance : {1e-3, 1e-6, 1e-9})
        row.push_back(needed(sweeps[s], cost_fits[s], kit::evaluations_per_step(s), tolerance, json["evaluations_needed"][kit::key(s)][fmt::format("{:.0e}", tolerance)]));
      double best = INFINITY;
      for (const Point& p : sweeps[s]) best = std::min(best, p.error);
      row.push_back(kit::sci(best, 2));
      cost.add_row(row);
    }
    out << "\nRight-hand-side evaluations needed at T (implicit Euler: one linear solve counted as one):\n";
    cost.print(out);

    // 5. The figures.
    if (app.options().no_plot) return;
    kit::Figure convergence("convergence", fmt::format("Error at T = {} s against Δt: each scheme's order is its slope", t_end));
    auto& loglog = convergence.panel("time step Δt [s]", "|x_N - x(T)| [m]");
    loglog.logx = loglog.logy = true;
    loglog.key = "outside right";
    kit::Figure work("work-precision", "What accuracy costs: error reached against right-hand-side evaluations");
    auto& wp = work.panel("right-hand-side evaluations over [0, T]", "|x_N - x(T)| [m]");
    wp.logx = wp.logy = true;
    wp.key = "outside right";
    for (const char* level : {"1e-3", "1e-6", "1e-9"}) {  // the tolerances of the printed table
      wp.commands.push_back(fmt::format("set arrow from graph 0, first {0} to graph 1, first {0} nohead dt 3 lc rgb '#aaaaaa'", level));
      wp.commands.push_back(fmt::format("set label '{0} m' at graph 0.01, first {0} offset 0,0.5 font ',8' tc rgb '#777777'", level));
    }
    for (Scheme s : kit::all_schemes) {
      std::vector<double> dt, error, evaluations;
      for (const Point& p : sweeps[s]) dt.push_back(p.dt), error.push_back(p.error), evaluations.push_back(double(p.evaluations));
      const std::string look = fmt::format("{} {}", kit::style(s), kit::marker(s));
      loglog.add({fmt::format("{}: order {:.2f}", kit::name(s), fits[s].slope), dt, error, "linespoints", look});
      wp.add({kit::name(s), evaluations, error, "linespoints", look});
    }
    app.figure(convergence);
    app.figure(work);

    kit::Figure energy("energy-drift", fmt::format("Energy error over {} periods (ω·Δt = 0.1): bounded for symplectic Euler", periods));
    auto& ep = energy.panel("time t [s]", "|E/E0 - 1|");
    ep.logy = true;
    ep.commands = {"set yrange [1e-8:1e3]"};
    ep.key = "outside right";
    for (Scheme s : kit::all_schemes) {
      std::vector<double> drift_values;
      for (const Vec2& u : energy_runs.at(s).u) drift_values.push_back(std::max(1e-16, std::abs(spring.energy(u) / e0 - 1)));
      const bool leaves = *std::max_element(drift_values.begin(), drift_values.end()) > 1e3;
      ep.add({std::string(kit::name(s)) + (leaves ? " (leaves the chart)" : ""), energy_runs.at(s).t, drift_values, "lines", kit::style(s)});
    }
    app.figure(energy);
  });
}
