#include "scheme_figures.hpp"

#include <algorithm>

#include <fmt/format.h>

#include <kit/app/look.hpp>

namespace kit {

namespace {
std::string looks(Scheme s) { return fmt::format("{} {}", style(s), marker(s)); }
}  // namespace

Figure convergence_figure(const std::map<Scheme, ConvergenceSweep>& sweeps, double t) {
  Figure figure("convergence",
                fmt::format("Error at T = {:.4g} s against Δt: each scheme's order is its slope", t));
  auto& panel = figure.panel("time step Δt [s]", "|x_N - x(T)| [m]");
  panel.logx = panel.logy = true;
  for (const auto& [s, sweep] : sweeps) {
    std::vector<double> dt, error;
    for (const SweepPoint& p : sweep.points) dt.push_back(p.dt), error.push_back(p.error);
    panel.add(
        {fmt::format("{}: order {:.2f}", name(s), sweep.order.slope), dt, error, "linespoints", looks(s)});
  }
  return figure;
}

Figure work_figure(const std::map<Scheme, ConvergenceSweep>& sweeps, const std::vector<double>& targets) {
  Figure figure("work-precision", "What accuracy costs: error reached against right-hand-side evaluations");
  auto& panel = figure.panel("right-hand-side evaluations over [0, T]", "|x_N - x(T)| [m]");
  panel.logx = panel.logy = true;
  for (double level : targets) {
    panel.commands.push_back(fmt::format(
        "set arrow from graph 0, first {0:.0e} to graph 1, first {0:.0e} nohead {1}", level, look::guide));
    panel.commands.push_back(fmt::format(
        "set label '{0:.0e} m' at graph 0.01, first {0:.0e} offset 0,0.5 {1}", level, look::guide_label));
  }
  for (const auto& [s, sweep] : sweeps) {
    std::vector<double> evaluations, error;
    for (const SweepPoint& p : sweep.points)
      evaluations.push_back(double(p.evaluations)), error.push_back(p.error);
    panel.add({name(s), evaluations, error, "linespoints", looks(s)});
  }
  return figure;
}

Figure energy_figure(const std::map<Scheme, EnergyDrift>& drifts, long periods) {
  Figure figure(
      "energy-drift",
      fmt::format("Energy error over {} periods (ω·Δt = 0.1): bounded for symplectic Euler", periods));
  auto& panel = figure.panel("time t [s]", "|E/E0 - 1|");
  panel.logy = true;
  panel.commands = {"set yrange [1e-8:1e3]"};
  for (const auto& [s, drift] : drifts) {
    std::vector<double> shown;  // a log axis has no 0
    for (double d : drift.drift) shown.push_back(std::max(1e-16, d));
    const bool leaves = *std::max_element(shown.begin(), shown.end()) > 1e3;
    panel.add(
        {std::string(name(s)) + (leaves ? " (leaves the chart)" : ""), drift.t, shown, "lines", style(s)});
  }
  return figure;
}

}  // namespace kit
