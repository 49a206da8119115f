// Chapter 7's figures (cloth_implicit_figures.hpp).
#include "cloth_implicit_figures.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include <kit/app/look.hpp>

namespace kit {

std::string cloth_method_style(const std::string& key) {
  static const std::map<std::string, std::string> styles{{"explicit-euler", look::explicit_euler},
                                                         {"symplectic-euler", look::symplectic_euler},
                                                         {"midpoint", look::midpoint},
                                                         {"rk4", look::rk4},
                                                         {"implicit-euler", look::implicit_euler},
                                                         {"newton", "lc rgb '#17becf'"},
                                                         {"liu", look::stable},
                                                         {"liu-iterations", look::stable + " dt 2"}};
  const auto it = styles.find(key);
  return it == styles.end() ? look::highlight : it->second;
}

Figure cloth_stiffness_figure(const std::vector<StiffnessRow>& rows, double h, const std::string& scene) {
  Figure fig("stiffness", fmt::format("Stiffer springs, smaller explicit steps ('{}' held at two corners); "
                                      "implicit: h = {:.3g} s",
                                      scene, h));
  auto& p = fig.panel("structural stiffness K [N/m]", "time step [s]");
  p.logx = p.logy = true;
  p.commands.push_back("set format x '10^{%T}'");
  std::vector<double> k, measured, predicted;
  for (const auto& r : rows)
    k.push_back(r.stiffness), measured.push_back(r.measured.estimate()), predicted.push_back(r.predicted);
  p.add({"symplectic Euler, largest stable Δt (measured)", k, measured, "linespoints",
         look::symplectic_euler + " lw 2 pt 7 ps 1.3"});
  p.points("symplectic Euler, 2/ω_{max}", k, predicted, look::prediction + " pt 6 ps 2");
  const double spread[] = {0.72, 1.0, 1.39};  // the three methods side by side, none hiding another
  for (const ImplicitMethod method : all_implicit_methods) {
    std::vector<double> ks, hs, kf, hf;
    for (const auto& r : rows)
      for (const auto& s : r.implicit) {
        if (s.method != method) continue;
        (s.stable ? ks : kf).push_back(r.stiffness * spread[int(method)]);
        (s.stable ? hs : hf).push_back(h);
      }
    if (!ks.empty())
      p.points(std::string(display_name(method)) + ": stable at h", ks, hs,
               cloth_method_style(flag_name(method)) + " pt 7 ps 1.5");
    if (!kf.empty())
      p.points(std::string(display_name(method)) + ": failed or gained energy", kf, hf,
               cloth_method_style(flag_name(method)) + " pt 2 ps 2 lw 2");
  }
  return fig;
}

Figure cloth_damping_figure(const Trade& trade, const std::string& scene) {
  Figure fig("damping", fmt::format("Numerical damping on '{}' (K = {:.3g} N/m, undamped springs): energy "
                                    "removed by t = {:.3g} s",
                                    scene, trade.stiffness, trade.t_end));
  auto& p = fig.panel("time step h [s]", "E_{ref}(t) − E(t) [J]  (> 0: removed by the method)");
  p.logx = p.logy = true;
  std::vector<std::string> keys;
  for (const auto& r : trade.runs)
    if (r.key != "liu-iterations" && (r.key == "implicit-euler" || r.key == "newton" || r.key == "liu") &&
        std::find(keys.begin(), keys.end(), r.key) == keys.end())
      keys.push_back(r.key);
  double lo = INFINITY, hi = 0;
  for (const auto& key : keys) {
    std::vector<double> h, lost;
    std::string name;
    for (const auto& r : trade.runs)
      if (r.key == key && !r.failed && r.energy_lost > 0)
        h.push_back(r.dt), lost.push_back(r.energy_lost), name = r.method;
    for (double x : h) lo = std::min(lo, x), hi = std::max(hi, x);
    if (!h.empty()) p.add({name, h, lost, "linespoints", cloth_method_style(key) + " lw 2 pt 7"});
  }
  if (hi > lo) {
    p.line(fmt::format("the swing's largest kinetic energy (t ≤ {:.3g} s)", trade.t_end), {lo, hi},
           {trade.energy_scale, trade.energy_scale}, look::prediction);
  }
  return fig;
}

Figure cloth_trade_figure(const Trade& trade, const std::string& scene) {
  Figure fig(
      "trade-timing",
      fmt::format("The cost of accuracy on '{}' ({} nodes across, K = {:.3g} N/m): error at t = {:.3g} s",
                  scene, trade.n, trade.stiffness, trade.t_end));
  auto& p = fig.panel("wall time of the run [s]",
                      "RMS node-position error [m]  (against RK4 at a twentieth of its limit)");
  p.logx = p.logy = true;
  std::vector<std::string> keys;
  for (const auto& r : trade.runs)
    if (std::find(keys.begin(), keys.end(), r.key) == keys.end()) keys.push_back(r.key);
  for (const auto& key : keys) {
    std::vector<double> seconds, error;
    std::string name;
    int iterations = 0;
    for (const auto& r : trade.runs)
      if (r.key == key && !r.failed)
        seconds.push_back(std::max(r.seconds, 1e-6)), error.push_back(r.error), name = r.method,
                                                                                iterations = r.iterations;
    if (key == "liu-iterations")
      name += ", 1 → 100 iterations";
    else if (key == "liu")
      name += fmt::format(", {} iterations", iterations);
    if (!seconds.empty())
      p.add({name, seconds, error, "linespoints", cloth_method_style(key) + " lw 2 pt 7"});
  }
  return fig;
}

Figure cloth_solver_figure(const std::vector<SolverPoint>& points, const std::string& scene) {
  Figure fig("solver", fmt::format("Conjugate gradients on '{}': iterations per step of the linearised "
                                   "implicit Euler",
                                   scene));
  auto& p = fig.panel("time step h [s]", "mean CG iterations per solve");
  p.logx = p.logy = true;
  const std::string colours[] = {look::implicit_euler, look::symplectic_euler, look::explicit_euler,
                                 look::stable};
  std::vector<double> stiffnesses;
  for (const auto& q : points)
    if (std::find(stiffnesses.begin(), stiffnesses.end(), q.stiffness) == stiffnesses.end())
      stiffnesses.push_back(q.stiffness);
  for (std::size_t c = 0; c < stiffnesses.size(); ++c)
    for (const ImplicitSolver solver : all_implicit_solvers) {
      std::vector<double> h, mean;
      for (const auto& q : points)
        if (q.solver == solver && q.stiffness == stiffnesses[c])
          h.push_back(q.h), mean.push_back(std::max(q.mean_iterations, 0.5));
      const char* line = solver == ImplicitSolver::cg    ? " lw 2 pt 6 dt 2"
                         : solver == ImplicitSolver::pcg ? " lw 2 pt 7"
                                                         : " lw 2 pt 5 dt 3";
      const std::string style = colours[c % 4] + line;
      p.add({fmt::format("{}, K = {:.0e} N/m", display_name(solver), stiffnesses[c]), h, mean, "linespoints",
             style});
    }
  return fig;
}

}  // namespace kit
