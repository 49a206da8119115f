// Chapter 6's figures (cloth_figures.hpp).
#include "cloth_figures.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <kit/app/look.hpp>
#include <kit/base/measure.hpp>

namespace kit {

std::string cloth_style(ClothIntegrator integrator) {
  switch (integrator) {
    case ClothIntegrator::explicit_euler:
      return look::explicit_euler;
    case ClothIntegrator::symplectic_euler:
      return look::symplectic_euler;
    case ClothIntegrator::midpoint:
      return look::midpoint;
    case ClothIntegrator::rk4:
      return look::rk4;
  }
  return look::highlight;
}

Figure cloth_energy_figure(const ClothRuns& runs, double dt, const std::string& scene) {
  Figure fig("energy", fmt::format("Energy of '{}' over time, each integrator at Δt = {:.3g} s", scene, dt));
  auto& p = fig.panel("time t [s]", "E(t) − E(0) [J]  (> 0: energy added by the method)");
  double lo = 0, hi = 0;
  bool off_scale = false;
  for (const auto& [integrator, rec] : runs) {
    std::vector<double> t, e;
    for (const ClothSample& s : rec.samples)
      t.push_back(s.t), e.push_back(s.total() - rec.samples.front().total());
    std::string title = display_name(integrator);
    if (rec.exploded_at >= 0) {
      title += fmt::format(" (explodes at t = {:.3g} s)", rec.exploded_at);
      off_scale = true;
    } else {
      for (double value : e) lo = std::min(lo, value), hi = std::max(hi, value);
    }
    p.add({title, t, e, "lines", cloth_style(integrator) + " lw 2"});
  }
  // An exploded run's energy dwarfs the others: the axis shows the runs that held.
  if (off_scale && hi > lo) {
    const double pad = 0.15 * (hi - lo);
    p.commands.push_back(fmt::format("set yrange [{}:{}]", lo - pad, hi + pad));
    fig.title += " (exploded runs leave the axis)";
  }
  // The runs that lose energy smoothly overlap at the scale of one that gains it: a second panel
  // shows only the runs whose change stays within 10% of the largest loss.
  double loss = 0;
  for (const auto& [integrator, rec] : runs)
    if (rec.exploded_at < 0) loss = std::min(loss, rec.samples.back().total() - rec.samples.front().total());
  if (loss < 0) {
    fig.height_in = 6.5;
    auto& zoom = fig.panel("time t [s]", "E(t) − E(0) [J]", "the runs that lose energy, enlarged");
    for (const auto& [integrator, rec] : runs) {
      const double change = rec.samples.back().total() - rec.samples.front().total();
      if (rec.exploded_at >= 0 || std::abs(change) > 10 * std::abs(loss)) continue;
      std::vector<double> t, e;
      for (const ClothSample& s : rec.samples)
        t.push_back(s.t), e.push_back(s.total() - rec.samples.front().total());
      zoom.add({display_name(integrator), t, e, "lines", cloth_style(integrator) + " lw 2"});
    }
  }
  double t_end = 0;
  for (const auto& [integrator, rec] : runs) t_end = std::max(t_end, rec.samples.back().t);
  for (Panel& panel : fig.panels) panel.commands.push_back(fmt::format("set xrange [0:{}]", t_end));
  return fig;
}

Figure cloth_strain_figure(const ClothRecording& free, const ClothRecording& limited, double max_strain,
                           const std::string& scene) {
  Figure fig("strain",
             fmt::format("The super-elastic effect in '{}': the most stretched structural spring", scene));
  auto& p = fig.panel("time t [s]", "largest stretch (l − L_0)/L_0 [%]  (> 0: longer than at rest)");
  for (const auto* rec : {&free, &limited}) {
    std::vector<double> t, strain;
    for (const ClothSample& s : rec->samples) t.push_back(s.t), strain.push_back(100 * s.strain);
    p.add({rec == &free ? "springs alone"
                        : fmt::format("with Provot's strain limit of {:.3g}%", 100 * max_strain),
           t, strain, "lines", (rec == &free ? look::unstable : look::stable) + " lw 2"});
  }
  if (!free.samples.empty()) {
    p.line("the limit", {0, free.samples.back().t}, {100 * max_strain, 100 * max_strain}, look::guide);
    p.commands.push_back(fmt::format("set xrange [0:{}]", free.samples.back().t));
  }
  return fig;
}

Figure cloth_stability_figure(const std::vector<StabilityCase>& rows, const std::string& scene) {
  Figure fig(
      "stability",
      fmt::format("The largest stable Δt on '{}': measured (filled) against c/ω_{{max}} (open)", scene));
  auto& p = fig.panel("spring layout", "largest stable step Δt_{max} [s]");
  p.logy = true;
  std::vector<std::string> layouts;
  for (const auto& row : rows)
    if (std::find(layouts.begin(), layouts.end(), row.layout) == layouts.end()) layouts.push_back(row.layout);
  std::string tics = "set xtics (";
  for (std::size_t k = 0; k < layouts.size(); ++k) {
    // A long layout name ("all three, μ = …") breaks after its comma, so that at a slide's
    // width it does not run into its neighbour's.
    std::string label = layouts[k];
    if (const auto comma = label.find(", "); comma != std::string::npos) label.replace(comma, 2, ",\n");
    tics += fmt::format("{}{} {}", k ? ", " : "", gnuplot_string(label), k);
  }
  p.commands.push_back(tics + ")");
  p.commands.push_back(fmt::format("set xrange [-0.5:{}]", double(layouts.size()) - 0.5));
  p.commands.push_back("set offsets 0, 0, graph 0.06, graph 0.06");  // no point on the frame
  p.commands.push_back("set key samplen 4 spacing 1.4");  // room in the legend for the large open circles
  for (ClothIntegrator integrator : all_cloth_integrators) {
    std::vector<double> x, measured, xp, predicted;
    // Each integrator's points sit a little apart within a layout's column so none hides another.
    const double shift = 0.12 * (double(int(integrator)) - 1.5);
    for (const auto& row : rows) {
      if (row.integrator != integrator) continue;
      const double column =
          double(std::find(layouts.begin(), layouts.end(), row.layout) - layouts.begin()) + shift;
      if (row.result.measured.estimate() > 0)
        x.push_back(column), measured.push_back(row.result.measured.estimate());
      if (row.result.predicted > 0) xp.push_back(column), predicted.push_back(row.result.predicted);
    }
    if (!x.empty())
      p.points(std::string(display_name(integrator)) + ", measured", x, measured,
               cloth_style(integrator) + " pt 7 ps 1.4");
    if (!xp.empty())
      p.points(std::string(display_name(integrator)) + ", predicted", xp, predicted,
               cloth_style(integrator) + " pt 6 ps 2.2 lw 2");
  }
  return fig;
}

Figure cloth_resolution_figure(const std::vector<StabilityAtResolution>& rows, const std::string& scene) {
  Figure fig(
      "resolution",
      fmt::format("'{}' at N nodes across, symplectic Euler: smaller steps, and many more of them", scene));
  fig.height_in = 6.5;
  auto& dt = fig.panel("nodes across N", "largest stable step Δt_{max} [s]", "the step shrinks like 1/N");
  auto& cost = fig.panel("nodes across N", "spring forces per simulated second", "the cost grows like N^3");
  std::vector<double> n, cells, measured, predicted, evaluations;
  for (const auto& r : rows) {
    n.push_back(r.n), cells.push_back(r.n - 1), measured.push_back(r.measured.estimate()),
        predicted.push_back(r.predicted);
    evaluations.push_back(r.spring_evaluations_per_second);
  }
  fig.left_edge = 0.1, fig.right_edge = 0.72;
  for (Panel* p : {&dt, &cost}) {
    p->logx = p->logy = true;
    p->commands.push_back("set xrange [12:90]");
    p->commands.push_back("set xtics (16, 32, 64)");
    p->commands.push_back("set format x '%g'");  // the node counts, not powers of ten
  }
  dt.points("measured", n, measured, look::symplectic_euler + " pt 7 ps 1.4");
  dt.points("2/ω_{max}", n, predicted, look::prediction + " pt 6 ps 2");
  cost.points("measured (at 0.9 Δt_{max})", n, evaluations, look::symplectic_euler + " pt 7 ps 1.4");
  if (rows.size() >= 2) {
    // Fitted against the cells across, N − 1: the grid step is the side over N − 1.
    const auto dt_fit = fit_loglog(cells, measured), cost_fit = fit_loglog(cells, evaluations);
    const auto fitted = [&](const LogLogFit& f) {
      std::vector<double> y;
      for (double x : cells) y.push_back(std::pow(10.0, f.intercept) * std::pow(x, f.slope));
      return y;
    };
    dt.line(fmt::format("fit: Δt_{{max}} ∝ (N−1)^{{{:.2f}}}", dt_fit.slope), n, fitted(dt_fit), look::guide);
    cost.line(fmt::format("fit: cost ∝ (N−1)^{{{:.2f}}}", cost_fit.slope), n, fitted(cost_fit), look::guide);
  }
  return fig;
}

Figure cloth_mesh_figure(const std::map<Hanging, std::vector<Sag>>& sags, double limit) {
  Figure fig("mesh", "Dépendance au maillage: one 1 m sheet hanging at rest, at N × N nodes");
  auto& p = fig.panel("nodes across N", "drop of the bottom edge's middle [mm]  (> 0: below its rest place)");
  p.logx = true;
  const std::string styles[] = {look::stable + " lw 2", look::unstable + " lw 2",
                                look::implicit_euler + " lw 2 dt 2", look::midpoint + " lw 2"};
  p.commands.push_back("set xrange [6:80]");
  p.commands.push_back("set xtics (8, 16, 32, 64)");
  p.commands.push_back("set format x '%g'");  // the node counts, not powers of ten
  double lo = INFINITY, hi = 0;
  for (const auto& [hanging, curve] : sags) {
    std::vector<double> n, drop;
    for (const Sag& s : curve)
      n.push_back(s.n), drop.push_back(1e3 * s.drop), lo = std::min(lo, double(s.n)),
                                                      hi = std::max(hi, double(s.n));
    p.add({describe(hanging), n, drop, "linespoints", styles[int(hanging)] + " pt 7"});
  }
  if (limit > 0 && hi > lo)
    p.line("top edge, same k: Richardson's limit N → ∞", {lo, hi}, {1e3 * limit, 1e3 * limit}, look::guide);
  return fig;
}

}  // namespace kit
