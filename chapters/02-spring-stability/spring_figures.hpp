#pragma once
// Chapter 2's six figures: the runs at Δt against the exact motion (positions, phase portraits,
// energy), and the schemes' stability (growth per step against ω·Δt, stability regions in the
// complex plane, and the measured stability map over (ω·Δt, ζ)). Chapter specific: they draw
// the selected methods' amplification factors (ex 2.4) and runs.
#include <string>

#include <fmt/format.h>

#include <kit/app/figure.hpp>
#include <kit/problems/spring.hpp>

#include "spring_stability.hpp"

namespace kit {

/// "m = 1 kg, K = 100 N/m, μ = 0 N·s/m, Δt = 0.02 s (ω·Δt = 0.2)": what a run's figure shows.
inline std::string run_note(const Spring& spring, double dt) {
  return fmt::format("m = {} kg, K = {} N/m, μ = {} N·s/m, Δt = {} s (ω·Δt = {:.3g})", spring.mass,
                     spring.stiffness, spring.damping, dt, spring.omega() * dt);
}

/// x(t) of every scheme over the exact motion.
inline Figure positions_figure(const Spring& spring, const Vec2& u0, double dt, double t_end,
                               const SpringRuns& runs) {
  Figure figure("positions", "Position over time: " + run_note(spring, dt));
  auto& xt = figure.panel("time t [s]", "position x [m]");
  const auto [t, x] = sample([&](double time) { return spring_motion(spring, u0, time)[0]; }, 0, t_end, 1000);
  xt.line("exact", t, x, look::exact);
  for (const auto& [s, run] : runs)
    xt.add({name(s), run.trajectory.t, run.trajectory.component(0), "linespoints",
            fmt::format("{} {} pi 5", style(s), marker(s))});
  return figure;
}

/// (x − L0, v) of the three Euler schemes around the exact ellipse (or spiral, when damped).
inline Figure phase_figure(const Spring& spring, const Vec2& u0, double t_end, const SpringRuns& runs) {
  Figure figure("phase",
                "Phase portraits: explicit Euler spirals out, implicit Euler in, symplectic Euler closes");
  auto& pv = figure.panel("displacement x - L0 [m]", "velocity v [m/s]");
  const auto exact = [&](int i) {  // component i of the exact state, sampled over [0, T]
    return sample([&](double time) { return spring_motion(spring, u0, time)[i]; }, 0, t_end, 1000).second;
  };
  std::vector<double> y = exact(0), v = exact(1);
  for (double& value : y) value -= spring.rest_length;
  pv.line("exact", y, v, look::exact);
  for (Scheme s : {Scheme::explicit_euler, Scheme::implicit_euler, Scheme::symplectic_euler}) {
    if (!runs.count(s)) continue;  // its exercise is not written yet
    std::vector<double> displacement = runs.at(s).trajectory.component(0);
    for (double& value : displacement) value -= spring.rest_length;
    pv.add({name(s), displacement, runs.at(s).trajectory.component(1), "lines", style(s)});
  }
  return figure;
}

/// E(t)/E(0) of every scheme on a log scale, over the exact energy (constant when undamped).
inline Figure energy_figure(const Spring& spring, const Vec2& u0, double dt, double t_end,
                            const SpringRuns& runs) {
  Figure figure("energy", "Energy E = ½mv² + ½K(x - L0)², relative to its start: " + run_note(spring, dt));
  auto& et = figure.panel("time t [s]", "E(t) / E(0)");
  et.logy = true;
  const double e0 = spring.energy(u0);
  for (const auto& [s, run] : runs) {
    std::vector<double> ratio;
    for (const Vec2& u : run.trajectory.u) ratio.push_back(spring.energy(u) / e0);
    et.add({name(s), run.trajectory.t, ratio, "lines", style(s)});
  }
  const auto relative = [&](double time) { return spring.energy(spring_motion(spring, u0, time)) / e0; };
  const auto [t, e] = sample(relative, 0, t_end, 1000);
  et.line("exact", t, e, look::exact + " dt 2");
  return figure;
}

/// The spectral radius of one step against ω·Δt at this spring's ζ, with this run's ω·Δt marked.
/// Symplectic Euler's curve comes from its step (ex 2.3): drawn once that is written.
inline Figure amplification_figure(double h, double zeta, const Written& written) {
  const std::string title = "Growth per step on this spring (ζ = {:.3g}) against ω·Δt: above 1 it diverges";
  Figure figure("amplification", fmt::format(fmt::runtime(title), zeta));
  auto& rh = figure.panel("ω·Δt (dimensionless)", "spectral radius of one step, |R|");
  rh.commands = {"set yrange [0:2]", fmt::format("set arrow from {0},0 to {0},2 nohead {1}", h, look::guide),
                 fmt::format("set label 'this run, ω·Δt = {:.3g}' at {},1.9 left offset 0.5,0", h, h)};
  for (Scheme s : all_schemes) {
    if (s == Scheme::symplectic_euler && !written.has(s)) continue;
    const auto [hs, rs] = sample([&](double x) { return spectral_radius(s, x, zeta); }, 0.0, 3.5, 700);
    rh.line(name(s), hs, rs, std::string(style(s)) + " lw 2");
  }
  rh.line("|R| = 1", {0.0, 3.5}, {1.0, 1.0}, look::prediction);
  return figure;
}

/// The boundaries |R(z)| = 1 in the complex plane, with this spring's z = λΔt.
inline Figure stability_regions_figure(double h, double zeta) {
  Figure figure("stability-regions", "Stability regions |R(z)| ≤ 1, with this spring's z = λΔt");
  figure.width_in = 6.5, figure.height_in = 5.5;
  auto& zplane = figure.panel("Re(λΔt)", "Im(λΔt)");
  zplane.commands = {"set size ratio -1", "set xrange [-4:3]", "set yrange [-3.5:3.5]",
                     "set label 'implicit Euler: stable OUTSIDE its circle' at 0.2,-3.2 font ',8'"};
  for (Scheme s : {Scheme::explicit_euler, Scheme::implicit_euler, Scheme::midpoint, Scheme::rk4}) {
    const auto [re, im] = region_boundary(s);
    zplane.points(std::string(name(s)) + " boundary", re, im, std::string(style(s)) + " pt 7 ps 0.3");
  }
  const auto z = oscillator_z(h, zeta);
  zplane.points(fmt::format("this spring: λΔt = {:.3g} ± {:.3g}i", z.first.real(), std::abs(z.first.imag())),
                {z.first.real(), z.second.real()}, {z.first.imag(), z.second.imag()},
                look::highlight + " pt 3 ps 2 lw 2");
  return figure;
}

/// One panel per scheme written: measured verdicts over (ω·Δt, ζ) and the analytic boundary.
inline Figure stability_map_figure(const Written& written) {
  Figure figure("stability-map",
                "Measured stability over (ω·Δt, ζ), 3000 steps each, with the analytic boundary");
  figure.columns = 3, figure.width_in = 10, figure.height_in = 6.5;
  for (Scheme s : written.schemes) {
    auto& panel = figure.panel("ω·Δt", "damping ratio ζ", name(s));
    panel.key = "below horizontal font ',8'";
    panel.commands = {"set xrange [0:4]", "set yrange [0:2]", "set bmargin 5"};
    const StabilityMap map = measure_stability_map(s, written.factors);
    panel.points("stable", map.stable_h, map.stable_zeta, look::stable + " pt 7 ps 0.3");
    panel.points("diverges", map.unstable_h, map.unstable_zeta, look::unstable + " pt 2 ps 0.5");
    panel.line(map.boundary_h.empty() ? "" : "analytic boundary", map.boundary_h, map.boundary_zeta,
               look::highlight + " lw 2");
  }
  return figure;
}

/// All six, in the order of the chapter's README; the two drawn from R(z) once ex 2.4 is written,
/// the stability map once a scheme is.
inline std::vector<Figure> spring_figures(const Spring& spring, const Vec2& u0, double dt, double t_end,
                                          const SpringRuns& runs, const Written& written) {
  const double h = spring.omega() * dt, zeta = spring.damping_ratio();
  std::vector<Figure> figures{positions_figure(spring, u0, dt, t_end, runs),
                              phase_figure(spring, u0, t_end, runs),
                              energy_figure(spring, u0, dt, t_end, runs)};
  if (written.factors) figures.push_back(amplification_figure(h, zeta, written));
  if (written.factors) figures.push_back(stability_regions_figure(h, zeta));
  if (!written.schemes.empty()) figures.push_back(stability_map_figure(written));
  return figures;
}

}  // namespace kit
