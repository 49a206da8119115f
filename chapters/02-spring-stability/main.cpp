// Chapter 2: stability of a mass on a spring (lecture, "Masses ressorts", "Précision/Stabilité").
// On an undamped spring, explicit Euler grows by sqrt(1 + ω²Δt²) every step, for every Δt
// (ERRATA item 4); implicit Euler shrinks by the inverse, for every Δt (item 5); symplectic
// Euler stays bounded while Δt < 2/ω (item 7). With damping, explicit Euler is stable iff
// Δt < μ/K (item 6). Each critical step is measured by bisection on long runs and printed
// beside theory.
#include <cmath>
#include <map>
#include <tuple>

#include <fmt/format.h>

#include <kit/chapter_app.hpp>
#include <kit/fixed_steps.hpp>
#include <kit/reference_solver.hpp>
#include <kit/spring.hpp>
#include <kit/spring_flags.hpp>
#include <kit/stability.hpp>
#include <kit/table.hpp>

#include "amplification.hpp"
#include "spring_steppers.hpp"

namespace {
using kit::Scheme;
using kit::Spring;
using kit::Vec2;

// Spectral radius of one step of `scheme` on the oscillator, from its analysis (h = ωΔt).
double radius(Scheme s, double h, double zeta) {
  if (s == Scheme::symplectic_euler) return kit::spectral_radius(kit::symplectic_euler_step_matrix(h, zeta));
  return kit::spectral_radius([s](std::complex<double> z) { return kit::amplification_factor(s, z); }, h, zeta);
}

// The critical step of `scheme` on `spring` [s]: analytic (where the spectral radius reaches 1)
// and measured (bisection on simulations long enough that a step 1e-4 past the limit doubles
// the amplitude, so the measurement resolves the limit to about 1e-4). NaN when measuring is
// not possible: no limit, or no bracket.
struct Critical {
  double analytic = NAN, measured = NAN;
};
Critical critical_step(Scheme s, const Spring& spring, long max_steps = 20'000'000) {
  const double w = spring.omega(), zeta = spring.damping_ratio();
  const double h = kit::stability_limit([&](double x) { return radius(s, x, zeta); }, 10.0);
  if (!(h > 0) || !std::isfinite(h)) return {h / w, NAN};
  const long steps = std::clamp(long(10.0 / (radius(s, 1.001 * h, zeta) - 1.0)), 20'000L, max_steps);
  const Vec2 u0(spring.rest_length + 0.1, 0.0), rest(spring.rest_length, 0.0);
  const auto unstable = [&](double dt) { return kit::grows(kit::spring_stepper(s, spring, dt), u0, rest, steps); };
  if (unstable(0.5 * h / w) || !unstable(1.5 * h / w)) return {h / w, NAN};
  return {h / w, kit::critical_step(unstable, 0.5 * h / w, 1.5 * h / w, 2e-5)};
}

// A growth factor: fixed with 12 decimals while readable, scientific beyond.
std::string factor_text(double value) { return std::abs(value) < 1e3 ? kit::fixed(value, 12) : kit::sci(value, 6); }

std::string limit_text(double dt) {
  if (dt == 0) return "none: unstable for every Δt (from ω·Δt = 0.01 on)";
  if (!std::isfinite(dt)) return "none: stable for every Δt";
  return kit::sci(dt, 5);
}
}  // namespace

int main(int argc, char** argv) {
  Spring spring;           // m = 1 kg, K = 100 N/m, μ = 0, L0 = 1 m
  Vec2 u0(1.5, 0.0);       // x0 [m], v0 [m/s]
  double dt = 0.02, t_end = 2.0;
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 2: stability of a mass on a spring");
  kit::add_spring_flags(app, spring, u0, 1e15);
  app.add_real("--dt", dt, "time step [s]", kit::positive(10.0));
  app.add_real("--t-end", t_end, "final time T [s], a whole number of steps", kit::positive(1e5));
  app.add_divergence_flag();

  return app.run(argc, argv, [&] {
    // 1. The system u' = A u + b: its frequency, damping ratio and eigenvalues.
    const long n = kit::whole_steps(t_end, dt);
    if (n == 0 || n > 1'000'000)
      throw kit::UsageError(fmt::format("--t-end {} / --dt {} = {:.6g} steps: expected a whole number in [1, 1e6]", t_end, dt, t_end / dt));
    kit::require_motion(spring, u0);
    auto& out = app.text();
    auto& json = app.summary();
    const double w = spring.omega(), zeta = spring.damping_ratio(), h = w * dt;
    const auto [l1, l2] = spring.eigenvalues();
    const char* regime = zeta == 0 ? "undamped" : zeta < 1 ? "underdamped" : zeta == 1 ? "critically damped" : "overdamped";
    out << fmt::format("Spring: m = {} kg, K = {} N/m, mu = {} N·s/m, L0 = {} m; u0 = ({} m, {} m/s)\n"
                       "omega = {:.6g} rad/s, zeta = {:.4g} ({}), period 2π/ω = {:.4g} s; dt = {} s, so omega·dt = {:.4g}\n"
                       "eigenvalues of A: {:.4g}{:+.4g}i and {:.4g}{:+.4g}i [1/s]\n\n", spring.mass, spring.stiffness,
                       spring.damping, spring.rest_length, u0[0], u0[1], w, zeta, regime, 2 * M_PI / w, dt, h,
                       l1.real(), l1.imag(), l2.real(), l2.imag());
    json.update({{"omega", w}, {"zeta", zeta}, {"omega_dt", h}, {"steps", n}});

    // 2. Every scheme at Δt against the closed form (which GSL cross-checks).
    std::vector<double> times;
    for (long k = 0; k <= n; ++k) times.push_back(double(k) * dt);
    // GSL only cross-checks the closed form; on extreme springs it may give up, which is reported.
    double gsl_gap = NAN;
    std::string gsl_note;
    try {
      kit::GslOptions cross_check;
      cross_check.max_steps = 2'000'000;  // thousands suffice on a normal spring; give up fast on extreme ones
      const auto gsl = kit::reference_solution(kit::spring_system(spring), 0.0, u0, times, cross_check);
      gsl_gap = 0;
      for (std::size_t k = 0; k < times.size(); ++k)
        gsl_gap = std::max(gsl_gap, std::abs(gsl.u[k][0] - kit::spring_motion(spring, u0, times[k])[0]));
    } catch (const kit::SolverError& e) {
      gsl_note = e.what();
    }
    const double e0 = spring.energy(u0), limit = 1e8 * (u0 - Vec2(spring.rest_length, 0)).norm() + std::abs(spring.rest_length);
    kit::Table runs({"scheme", "x(T) [m]", "|x(T) - exact|", "E(T)/E(0)", "growth/step", "spectral radius", "status"});
    std::map<Scheme, kit::Trajectory<Vec2>> trajectories;
    for (Scheme s : kit::all_schemes) {
      auto run = kit::record(u0, dt, n, kit::spring_stepper(s, spring, dt), limit);
      const Vec2 last = run.u.back();
      const long steps = long(run.size()) - 1;
      double max_drift = 0;  // max |E/E0 − 1| over the run
      for (const Vec2& u : run.u) max_drift = std::max(max_drift, std::abs(spring.energy(u) / e0 - 1));
      const bool diverged = bool(run.divergence);
      const double energy_ratio = spring.energy(last) / e0, growth = std::pow(energy_ratio, 0.5 / double(std::max(1L, steps)));
      const std::string status = diverged ? run.divergence->describe() : "finished";
      if (diverged) app.diverged(kit::name(s), status);
      // A diverged run ends before T: its last finite state says nothing about E(T) or the growth.
      runs.add_row({kit::name(s), diverged ? "-" : kit::fixed(last[0], 6),
                    diverged ? "-" : kit::sci(std::abs(last[0] - kit::spring_motion(spring, u0, t_end)[0]), 3),
                    diverged ? "-" : kit::sci(energy_ratio, 4), diverged ? "-" : factor_text(growth),
                    factor_text(radius(s, h, zeta)), status});
      json["runs"][kit::key(s)] = {{"x_end", diverged ? nlohmann::json() : nlohmann::json(last[0])},
                                   {"energy_ratio", diverged ? nlohmann::json() : nlohmann::json(energy_ratio)},
                                   {"growth_per_step", diverged ? nlohmann::json() : nlohmann::json(growth)},
                                   {"max_energy_drift", diverged ? nlohmann::json() : nlohmann::json(max_drift)},
                                   {"spectral_radius", radius(s, h, zeta)}, {"steps", steps}, {"diverged", diverged}};
      trajectories.emplace(s, std::move(run));
    }
    runs.print(out);
    out << fmt::format("growth/step = (E_N/E_0)^(1/2N); exact for explicit Euler when undamped: sqrt(1 + (ω·dt)²) = {}\n",
                       factor_text(std::sqrt(1 + h * h)));
    out << (gsl_note.empty() ? fmt::format("GSL rk8pd against the closed form: max |x_gsl - x_exact| = {:.3g} m\n", gsl_gap)
                             : fmt::format("GSL rk8pd cross-check unavailable on this spring: {}\n", gsl_note));
    json["reference_max_gap"] = gsl_note.empty() ? nlohmann::json(gsl_gap) : nlohmann::json();

    // 3. Critical steps, measured by bisection, beside theory.
    kit::Table table({"scheme", "spring", "measured Δt [s]", "from R(z) [s]", "closed form [s]", "measured vs closed form"});
    Spring damped = spring, undamped = spring;  // the textbook cases below
    if (!(zeta > 0 && zeta < 1)) damped.damping = 0.2 * std::sqrt(spring.stiffness * spring.mass);  // ζ = 0.1
    undamped.damping = 0;
    struct Case { Scheme scheme; Spring spring; double closed_form; const char* formula; };
    for (const Case& c : {Case{Scheme::explicit_euler, damped, damped.damping / damped.stiffness, "μ/K"},
                          Case{Scheme::symplectic_euler, undamped, 2.0 / w, "2/ω"}, Case{Scheme::rk4, undamped, 2.0 * std::sqrt(2.0) / w, "2√2/ω"}}) {
      const Critical crit = critical_step(c.scheme, c.spring);
      const double diff = (crit.measured - c.closed_form) / c.closed_form;
      table.add_row({kit::name(c.scheme), fmt::format("μ = {:.4g} (ζ = {:.3g})", c.spring.damping, c.spring.damping_ratio()),
                     kit::sci(crit.measured, 6), kit::sci(crit.analytic, 6), fmt::format("{} = {}", c.formula, kit::sci(c.closed_form, 6)),
                     fmt::format("{:+.2e}", diff)});
      json["critical"][kit::key(c.scheme)] = {{"damping", c.spring.damping}, {"measured", crit.measured},
                                              {"analytic", crit.analytic}, {"closed_form", c.closed_form}, {"relative_difference", diff}};
    }
    out << "\nCritical steps (bisection on long runs; above them the motion grows without bound):\n";
    table.print(out);
    out << "On this spring as given:";
    for (Scheme s : kit::all_schemes) {
      const Critical crit = critical_step(s, spring, 2'000'000);  // a shorter horizon: printed, not tested
      out << fmt::format("  {}: {};", kit::name(s), limit_text(crit.analytic));
      json["limits_as_given"][kit::key(s)] = {{"analytic", crit.analytic}, {"measured", crit.measured}};
    }
    out << "\n";

    // 4. Extremes: how much implicit Euler damps, and which schemes survive stiff springs.
    kit::Table loss({"ω·Δt", "amplitude kept per step", "1/sqrt(1+ω²Δt²)", "per period of the motion", "predicted"});
    for (double hh : {0.01, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0}) {
      // Few enough steps that the energy stays far above round-off (1e-12 of where it started).
      const long steps = std::clamp(long(27.0 / std::log(1 + hh * hh)), 1L, 50L);
      const auto end = kit::advance(u0, steps, kit::spring_stepper(Scheme::implicit_euler, undamped, hh / w));
      const double per_step = std::pow(undamped.energy(end) / undamped.energy(u0), 0.5 / double(steps));
      const double predicted = 1 / std::sqrt(1 + hh * hh);
      const bool period_spans_a_step = 2 * M_PI / hh >= 1;  // else "per period" would be a fraction of one step
      loss.add_row({kit::fixed(hh, 2), kit::sci(per_step, 8), kit::sci(predicted, 8),
                    period_spans_a_step ? kit::sci(std::pow(per_step, 2 * M_PI / hh), 4) : "- (period < Δt)",
                    period_spans_a_step ? kit::sci(std::pow(predicted, 2 * M_PI / hh), 4) : "-"});
      json["implicit_damping"].push_back({{"omega_dt", hh}, {"per_step", per_step}, {"predicted_per_step", predicted}});
    }
    out << "\nImplicit Euler damps the motion away as ω·Δt grows (undamped spring):\n";
    loss.print(out);
    kit::Table extremes({"spring", "ζ", "ω·Δt", "explicit Euler", "implicit Euler", "symplectic Euler", "midpoint RK2", "RK4"});
    for (auto [label, k_factor, z] : {std::tuple{"undamped (μ = 0)", 1.0, 0.0}, {"critical damping", 1.0, 1.0}, {"overdamped", 1.0, 3.0},
                                     {"stiff, ω×100", 1e4, 0.0}, {"stiff, ω = 1e6 rad/s", 1e12 * spring.mass / spring.stiffness, 0.0}}) {
      Spring variant = spring;
      variant.stiffness *= k_factor;
      variant.damping = 2 * z * std::sqrt(variant.stiffness * variant.mass);
      std::vector<std::string> row{label, kit::fixed(z, 1), kit::sci(variant.omega() * dt, 3)};
      for (Scheme s : kit::all_schemes) {
        const auto run = kit::record(u0, dt, 1000, kit::spring_stepper(s, variant, dt), limit);
        const double factor = std::sqrt(variant.energy(run.u.back()) / variant.energy(u0));  // amplitude, in the energy norm
        row.push_back(run.divergence ? fmt::format("diverged at step {}", run.divergence->step) : fmt::format("×{:.3g}", factor));
        json["extremes"][label][kit::key(s)] = run.divergence ? run.divergence->step : -1;
      }
      extremes.add_row(row);
    }
    out << fmt::format("\nExtremes, 1000 steps of dt = {} s: the amplitude after them, sqrt(E/E0), as a multiple of the start\n"
                       "(diverged: |u| passed 1e8 times the starting distance from rest):\n", dt);
    extremes.print(out);

    // 5. The figures (not even computed under --no-plot).
    if (app.options().no_plot) return;
    const std::string title_note = fmt::format("m = {} kg, K = {} N/m, μ = {} N·s/m, Δt = {} s (ω·Δt = {:.3g})",
                                               spring.mass, spring.stiffness, spring.damping, dt, h);
    std::vector<double> fine_t, fine_x, fine_y, fine_v;
    for (int i = 0; i <= 1000; ++i) {
      const double t = t_end * i / 1000.0;
      const Vec2 exact = kit::spring_motion(spring, u0, t);
      fine_t.push_back(t), fine_x.push_back(exact[0]), fine_y.push_back(exact[0] - spring.rest_length), fine_v.push_back(exact[1]);
    }
    kit::Figure positions("positions", "Position over time: " + title_note);
    auto& xt = positions.panel("time t [s]", "position x [m]");
    xt.key = "outside right";
    xt.line("exact", fine_t, fine_x, kit::look::exact);
    for (Scheme s : kit::all_schemes)
      xt.add({kit::name(s), trajectories.at(s).t, trajectories.at(s).component(0), "linespoints", fmt::format("{} {} pi 5", kit::style(s), kit::marker(s))});
    app.figure(positions);

    kit::Figure phase("phase", "Phase portraits: explicit Euler spirals out, implicit Euler in, symplectic Euler closes");
    auto& pv = phase.panel("displacement x - L0 [m]", "velocity v [m/s]");
    pv.key = "outside right";
    pv.line("exact", fine_y, fine_v, kit::look::exact);
    for (Scheme s : {Scheme::explicit_euler, Scheme::implicit_euler, Scheme::symplectic_euler}) {
      std::vector<double> y = trajectories.at(s).component(0);
      for (double& value : y) value -= spring.rest_length;
      pv.add({kit::name(s), y, trajectories.at(s).component(1), "lines", kit::style(s)});
    }
    app.figure(phase);

    kit::Figure energy("energy", "Energy E = ½mv² + ½K(x - L0)², relative to its start: " + title_note);
    auto& et = energy.panel("time t [s]", "E(t) / E(0)");
    et.logy = true;
    et.key = "outside right";
    for (Scheme s : kit::all_schemes) {
      std::vector<double> ratio;
      for (const Vec2& u : trajectories.at(s).u) ratio.push_back(spring.energy(u) / e0);
      et.add({kit::name(s), trajectories.at(s).t, ratio, "lines", kit::style(s)});
    }
    std::vector<double> exact_energy;
    for (std::size_t i = 0; i < fine_t.size(); ++i) exact_energy.push_back(spring.energy(Vec2(fine_x[i], fine_v[i])) / e0);
    et.line("exact", fine_t, exact_energy, kit::look::exact + " dt 2");
    app.figure(energy);

    kit::Figure gain("amplification", fmt::format("Growth per step on this spring (ζ = {:.3g}) against ω·Δt: above 1 it diverges", zeta));
    auto& rh = gain.panel("ω·Δt (dimensionless)", "spectral radius of one step, |R|");
    rh.key = "outside right";
    rh.commands = {"set yrange [0:2]", fmt::format("set arrow from {0},0 to {0},2 nohead dt 3 lc rgb '#888888'", h),
                   fmt::format("set label 'this run, ω·Δt = {:.3g}' at {},1.9 left offset 0.5,0", h, h)};
    for (Scheme s : kit::all_schemes) {
      std::vector<double> hs, rs;
      for (int i = 0; i <= 700; ++i) hs.push_back(3.5 * i / 700.0), rs.push_back(radius(s, hs.back(), zeta));
      rh.line(kit::name(s), hs, rs, std::string(kit::style(s)) + " lw 2");
    }
    rh.line("|R| = 1", {0.0, 3.5}, {1.0, 1.0}, kit::look::prediction);
    app.figure(gain);

    kit::Figure regions("stability-regions", "Stability regions |R(z)| ≤ 1, with this spring's z = λΔt");
    regions.width_in = 6.5, regions.height_in = 5.5;
    auto& zplane = regions.panel("Re(λΔt)", "Im(λΔt)");
    zplane.key = "outside right";
    zplane.commands = {"set size ratio -1", "set xrange [-4:3]", "set yrange [-3.5:3.5]",
                       "set label 'implicit Euler: stable OUTSIDE its circle' at 0.2,-3.2 font ',8'"};
    for (Scheme s : {Scheme::explicit_euler, Scheme::implicit_euler, Scheme::midpoint, Scheme::rk4}) {
      const auto dots = kit::level_set_points([s](double x, double y) { return std::abs(kit::amplification_factor(s, {x, y})); },
                                              1.0, -4, 3, -3.5, 3.5, 350, 350);
      std::vector<double> re, im;
      for (auto [x, y] : dots) re.push_back(x), im.push_back(y);
      zplane.points(std::string(kit::name(s)) + " boundary", re, im, std::string(kit::style(s)) + " pt 7 ps 0.3");
    }
    const auto z = kit::oscillator_z(h, zeta);
    zplane.points(fmt::format("this spring: λΔt = {:.3g} ± {:.3g}i", z.first.real(), std::abs(z.first.imag())),
                  {z.first.real(), z.second.real()}, {z.first.imag(), z.second.imag()}, kit::look::highlight + " pt 3 ps 2 lw 2");
    app.figure(regions);

    kit::Figure map("stability-map", "Measured stability over (ω·Δt, ζ), 3000 steps each, with the analytic boundary");
    map.columns = 3, map.width_in = 10, map.height_in = 6.5;
    for (Scheme s : kit::all_schemes) {
      auto& panel = map.panel("ω·Δt", "damping ratio ζ", kit::name(s));
      panel.key = "below horizontal font ',8'";
      panel.commands = {"set xrange [0:4]", "set yrange [0:2]", "set bmargin 5"};
      std::vector<double> sh, sz, uh, uz, bh, bz;
      for (int i = 1; i <= 40; ++i) {
        for (int j = 0; j <= 20; ++j) {
          Spring unit;  // ω = 1 rad/s, so Δt = ω·Δt
          unit.mass = 1, unit.stiffness = 1, unit.rest_length = 0, unit.damping = 2 * 0.1 * j;
          const bool blows_up = kit::grows(kit::spring_stepper(s, unit, 0.1 * i), Vec2(1, 0), Vec2(0, 0), 3000);
          (blows_up ? uh : sh).push_back(0.1 * i), (blows_up ? uz : sz).push_back(0.1 * j);
        }
      }
      for (int j = 0; j <= 200; ++j) {
        const double zj = 0.01 * j, limit_h = kit::stability_limit([&](double x) { return radius(s, x, zj); }, 4.0, 400, 1e-6);
        if (limit_h > 0 && std::isfinite(limit_h)) bh.push_back(limit_h), bz.push_back(zj);
      }
      panel.points("stable", sh, sz, "pt 7 ps 0.3 lc rgb '#2ca02c'");
      panel.points("diverges", uh, uz, "pt 2 ps 0.5 lc rgb '#d62728'");
      panel.line(bh.empty() ? "" : "analytic boundary", bh, bz, kit::look::highlight + " lw 2");
    }
    app.figure(map);
  });
}
