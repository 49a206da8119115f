// Chapter 9's figures (continuum_figures.hpp).
#include "continuum_figures.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <kit/app/look.hpp>

namespace kit {
namespace {

/// The relaxations drawn dashed, so that the three St Venant–Kirchhoff solvers differ by more than their
/// points.
std::string dashes(TipSolver solver) {
  return solver == TipSolver::explicit_relaxation   ? " dt 2"
         : solver == TipSolver::implicit_relaxation ? " dt 3"
                                                    : "";
}

const char* model_title(FemModel model) {
  switch (model) {
    case FemModel::linear:
      return "linear FEM";
    case FemModel::stvk:
      return "St Venant–Kirchhoff FEM";
    case FemModel::springs:
      return "springs";
  }
  return "?";
}

}  // namespace

std::string model_style(FemModel model) {
  switch (model) {
    case FemModel::linear:
      return look::explicit_euler;
    case FemModel::stvk:
      return look::implicit_euler;
    case FemModel::springs:
      return look::symplectic_euler;
  }
  return look::highlight;
}

Figure cantilever_figure(const std::map<FemModel, TipConvergence>& models, const FemMaterial& material) {
  const double euler_bernoulli = euler_bernoulli_tip(material);
  Figure fig("cantilever",
             fmt::format("A cantilever under its own weight, 1 m × 0.1 m: Euler–Bernoulli's tip "
                         "qL^4/(8EI) is {:.4g} mm",
                         1e3 * euler_bernoulli));
  fig.columns = 2;
  fig.width_in = 10;
  fig.height_in = 4.2;
  auto& tip = fig.panel("elements", "tip / Euler–Bernoulli's", "the tip (below 1: too stiff)");
  tip.logx = true;
  tip.key = "bottom right";
  auto& error = fig.panel("elements", "|tip − its limit| / limit", "discretisation error");
  error.logx = error.logy = true;
  error.key = "bottom left";
  double last = 0;
  for (const auto& [model, c] : models) {
    std::vector<double> n, ratio, distance;
    for (const auto& r : c.runs) {
      if (!r.done) continue;  // Newton failed: no tip to show
      n.push_back(double(r.elements));
      ratio.push_back(r.tip / euler_bernoulli);
      distance.push_back(magnitude_on_log_axis((r.tip - c.richardson.limit) / c.richardson.limit));
    }
    if (!n.empty()) last = std::max(last, n.back());
    // At 1.5 µm of sag the linear and St Venant–Kirchhoff tips agree to 1e-5: the linear curve is
    // dashed over open circles so that neither hides the other.
    const std::string look =
        model_style(model) + (model == FemModel::linear ? " lw 2 dt 2 pt 6 ps 1.8" : " lw 2 pt 7");
    tip.line(model_title(model), n, ratio, look).with = "linespoints";
    if (!c.richardson.converges || n.size() < 2) continue;  // no limit to measure from
    // The finest mesh sits on Richardson's limit by construction: left out of the right panel.
    n.pop_back();
    distance.pop_back();
    // The cell size h goes as elements^−½: an error ∝ h^p falls as elements^(−p/2) on this axis.
    error
        .line(
            fmt::format("{}: elements^{{−{:.2f}}} = h^{{{:.2f}}}", model_title(model), c.order / 2, c.order),
            n, distance, look)
        .with = "linespoints";
  }
  const double timoshenko = timoshenko_tip(material) / euler_bernoulli;
  tip.line("Euler–Bernoulli", {10, last}, {1, 1}, look::exact);
  tip.line(fmt::format("Timoshenko (shear), {:.4f}", timoshenko), {10, last}, {timoshenko, timoshenko},
           look::guide + " lw 2");
  return fig;
}

Figure turn_figure(const std::vector<TurnedElement>& sweep) {
  Figure fig("turned-element",
             "One element turned rigidly in its plane: what each strain sees, and the forces "
             "that follow");
  fig.columns = 2;
  fig.width_in = 10;
  fig.height_in = 4;
  std::vector<double> deg, cauchy, green, linear, stvk;
  for (const auto& t : sweep) {
    deg.push_back(t.degrees);
    cauchy.push_back(magnitude_on_log_axis(t.cauchy_strain));
    green.push_back(magnitude_on_log_axis(t.green_strain));
    linear.push_back(magnitude_on_log_axis(t.linear_force));
    stvk.push_back(magnitude_on_log_axis(t.stvk_force));
  }
  auto& strains = fig.panel("turn [degrees]", "strain |ε|, |E| (Frobenius)", "strain of a rigid turn");
  strains.logy = true;
  strains.key = "center right";
  strains.line("small strain ε (linear FEM)", deg, cauchy, model_style(FemModel::linear) + " lw 2");
  strains.line("Green's E (St Venant–Kirchhoff): round-off, 0 drawn at 1e-17", deg, green,
               model_style(FemModel::stvk) + " lw 2");
  strains.commands.push_back("set xrange [0:180]");
  strains.commands.push_back("set xtics 45");
  auto& forces = fig.panel("turn [degrees]", "largest nodal force / that of a 1% stretch", "ghost forces");
  forces.logy = true;
  forces.key = "center right";
  forces.line("linear FEM", deg, linear, model_style(FemModel::linear) + " lw 2");
  forces.line("St Venant–Kirchhoff: round-off, 0 drawn at 1e-17", deg, stvk,
              model_style(FemModel::stvk) + " lw 2");
  forces.commands.push_back("set xrange [0:180]");
  forces.commands.push_back("set xtics 45");
  return fig;
}

Figure plate_figure(const std::map<FemModel, PlateRun>& runs, const std::string& integrator) {
  Figure fig(
      "spinning-plate",
      fmt::format("A free plate spun at π rad/s ({} Euler): the linear model cannot turn", integrator));
  fig.columns = 2;
  fig.width_in = 10;
  fig.height_in = 4;
  auto& strain = fig.panel("time t [s]", "largest Green strain |E|", "how far from its rest shape");
  strain.logy = true;
  strain.key = "bottom right";
  auto& angle = fig.panel("time t [s]", "turned [rad]", "how far it turned (counter-clockwise > 0)");
  angle.key = "top left";
  for (const auto& [model, run] : runs) {
    std::vector<double> t, e, a;
    for (const auto& s : run.samples)
      t.push_back(s.t), e.push_back(magnitude_on_log_axis(s.strain)), a.push_back(s.angle);
    strain.line(model_title(model), t, e, model_style(model) + " lw 2");
    angle.line(model_title(model), t, a, model_style(model) + " lw 2");
  }
  if (!runs.empty() && !runs.begin()->second.samples.empty()) {
    const double t_end = runs.begin()->second.samples.back().t;
    const auto [t, exact] = sample([](double s) { return plate_spin * s; }, 0, t_end, 50);
    angle.line("rigid turn ωt", t, exact, look::guide + " lw 1.5");
  }
  return fig;
}

Figure plate_shapes_figure(const std::map<FemModel, std::vector<TimedOutline>>& outlines) {
  Figure fig("plate-shapes",
             "The spinning plate's outline: St Venant–Kirchhoff turns it; the linear model lets "
             "every node leave along its tangent, and the plate grows");
  fig.columns = int(outlines.size());
  fig.width_in = 10;
  fig.height_in = 4.2;
  const char* shades[] = {"#000000", "#1f77b4", "#ff7f0e", "#2ca02c"};
  for (const auto& [model, list] : outlines) {
    auto& p = fig.panel("x [m]", "y [m]", model_title(model));
    p.key = "outside right";
    p.commands.push_back("set size ratio -1");
    p.commands.push_back("set key invert");  // the legend in time order
    // The start is drawn last, dashed: a plate that has turned by π lies exactly on it.
    for (std::size_t k = list.size(); k-- > 0;) {
      std::vector<double> x, y;
      for (const auto& [px, py] : list[k].second) x.push_back(px), y.push_back(py);
      p.line(fmt::format("t = {:.3g} s", list[k].first), x, y,
             fmt::format("lc rgb '{}' lw 2{}", shades[std::min<std::size_t>(k, 3)], k == 0 ? " dt 2" : ""));
    }
  }
  return fig;
}

Figure stretch_figure(const std::map<FemModel, std::vector<StretchRow>>& rows) {
  Figure fig("mesh-dependence",
             "A sheet clamped on one edge and pulled on the other: the stretch on regular and "
             "irregular meshes");
  auto& p = fig.panel("cells per side n", "stretch / (σL/E)");
  p.logx = true;
  for (const auto& [model, list] : rows) {
    std::vector<double> n_regular, regular, n_irregular, irregular;  // a failed solve leaves its point out
    for (const auto& r : list) {
      if (r.regular) n_regular.push_back(r.n), regular.push_back(*r.regular);
      if (r.irregular) n_irregular.push_back(r.n), irregular.push_back(*r.irregular);
    }
    p.line(fmt::format("{}, regular mesh", model_title(model)), n_regular, regular,
           model_style(model) + " lw 2 pt 7")
        .with = "linespoints";
    p.line(fmt::format("{}, irregular mesh", model_title(model)), n_irregular, irregular,
           model_style(model) + " lw 2 dt 2 pt 6")
        .with = "linespoints";
  }
  p.commands.push_back("set xtics (4, 8, 16, 32, 64)");
  p.commands.push_back("set format x '%g'");
  p.commands.push_back("set xrange [3:90]");
  return fig;
}

Figure trade_figure(const std::vector<std::vector<TipRun>>& series) {
  Figure fig("trade-timing",
             "What the cantilever's accuracy costs: each point one mesh, 20 to 1280 elements");
  auto& p = fig.panel("wall time [s]", "|tip / Euler–Bernoulli − 1|");
  p.logx = p.logy = true;
  const char* points[] = {"pt 7", "pt 5", "pt 9", "pt 11", "pt 13"};
  int k = 0;
  for (const auto& list : series) {
    if (list.empty()) continue;
    std::vector<double> t, e;
    for (const auto& r : list)
      if (r.done) t.push_back(std::max(r.seconds, 1e-6)), e.push_back(magnitude_on_log_axis(r.error));
    p.line(fmt::format("{}, {}", model_title(list.front().model), solver_name(list.front().solver)), t, e,
           model_style(list.front().model) + " lw 2 " + points[k++ % 5] + dashes(list.front().solver))
        .with = "linespoints";
  }
  return fig;
}

}  // namespace kit
