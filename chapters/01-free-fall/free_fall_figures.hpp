#pragma once
// Chapter 1's four figures, each with its sign convention (ERRATA item 3): the trajectories
// against the parabola, the error growing linearly in time, the orders, and round-off. Chapter
// specific: the error-vs-time figure runs the selected Euler methods at Δt/2 and Δt/4.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include <kit/app/figure.hpp>
#include <kit/ode/power_law.hpp>
#include <kit/ode/trajectory_error.hpp>

#include "free_fall_euler.hpp"

namespace kit {

/// "y axis up, g < 0" or "y axis up, g > 0": what "above" means in every figure.
inline std::string axes_convention(const FreeFall& fall) {
  return fall.g < 0 ? "y axis up, g < 0" : "y axis up, g > 0";
}

/// x_k − x̃(t_k) [m] along a run: positive = above the exact parabola.
inline std::vector<double> gap(const FreeFall& fall, const Trajectory<Vec2>& run) {
  return deviation(run, [&](double t) { return fall.position(t); });
}

/// The same for a run that may not have been made (its exercise not written yet): empty then.
inline std::vector<double> gap(const FreeFall& fall, const std::optional<Trajectory<Vec2>>& run) {
  return run ? gap(fall, *run) : std::vector<double>{};
}

/// Heights against time (exact, both Euler, GSL) over the gap x − x̃ of both Euler schemes.
inline Figure trajectories_figure(const FreeFall& fall, double dt, double t_end, const EulerRuns& runs) {
  const std::string red = look::explicit_euler, blue = look::implicit_euler;
  Figure figure("trajectories", fmt::format("Free fall with Δt = {} s ({})", dt, axes_convention(fall)));
  figure.height_in = 5.5;
  figure.left_edge = 0.09, figure.right_edge = 0.74;
  auto& top = figure.panel("time t [s]", "height x [m]", "positions");
  top.place = {{0.0, 0.36, 1.0, 0.57}};
  const auto [t, x] = sample([&](double time) { return fall.position(time); }, 0.0, t_end);
  top.line("exact x0 + v0·t + g·t²/2", t, x, look::exact);
  // Only the schemes whose exercise is written are drawn (explicit: ex 1.2, or the loop of ex 1.1).
  const std::vector<std::tuple<std::string, const std::optional<Trajectory<Vec2>>*, std::string>> schemes{
      {"explicit Euler", &runs.explicit_run(), red + " pt 7 ps 0.8"},
      {"implicit Euler", &runs.impl, blue + " pt 6"}};
  for (const auto& [name, run, style] : schemes)
    if (*run) top.add({name, (*run)->t, (*run)->component(0), "linespoints", style});
  top.points("GSL rk8pd reference", runs.reference.t, runs.reference.component(0), look::reference + " pt 2");
  auto& below =
      figure.panel("time t [s]", "x - x_{exact} [m]", "the gap (positive = above the exact parabola)");
  below.place = {{0.0, 0.0, 1.0, 0.36}};
  for (const auto& [name, run, style] : schemes)
    if (*run) below.add({name, (*run)->t, gap(fall, **run), "linespoints", style});
  // A short panel: about three y tics, at a step of 1, 2 or 5 times a power of ten.
  double largest = 0;
  for (const auto& series : below.series)
    for (double y : series.y) largest = std::max(largest, std::isfinite(y) ? std::abs(y) : 0.0);
  if (largest > 0) {
    const double decade = std::pow(10.0, std::floor(std::log10(largest / 2))), wanted = largest / 2;
    const double step = wanted <= decade       ? decade
                        : wanted <= 2 * decade ? 2 * decade
                        : wanted <= 5 * decade ? 5 * decade
                                               : 10 * decade;
    below.commands.push_back(fmt::format("set ytics {:g}", step));
  }
  return figure;
}

/// The signed error against time for Δt, Δt/2 and Δt/4, on the predicted lines ±t·Δt·|g|/2, for
/// the schemes whose exercise is written (`runs` says which).
inline Figure error_growth_figure(const FreeFall& fall, double dt, double t_end, const EulerRuns& runs) {
  const double g = std::abs(fall.g);
  Figure figure("error-vs-time", fmt::format("Euler's error grows linearly in time, with slope Δt·|g|/2 ({})",
                                             axes_convention(fall)));
  auto& lines = figure.panel("time t [s]", "x_k - x_{exact}(t_k) [m]   (positive = above)");
  for (auto [h, mark] : {std::pair{dt, 7}, {dt / 2, 9}, {dt / 4, 5}}) {
    if (runs.explicit_run()) {  // the matrix form (ex 1.2), else the lecture's loop (ex 1.1): same numbers
      long evals = 0;
      const auto e = runs.expl ? explicit_matrix_form(fall, t_end, h)
                               : lecture_loop(fall, h, whole_steps(t_end, h), evals);
      lines.points(fmt::format("explicit, Δt = {:g} s", h), e.t, gap(fall, e),
                   look::explicit_euler + fmt::format(" pt {} ps 0.9", mark));
    }
    if (runs.impl) {
      const auto i = implicit_matrix_form(fall, t_end, h);
      lines.points(fmt::format("implicit, Δt = {:g} s", h), i.t, gap(fall, i),
                   look::implicit_euler + fmt::format(" pt {} ps 0.9", mark - 1));
    }
    const auto t = sample([](double time) { return time; }, 0.0, t_end).first;
    lines.line(h == dt ? "prediction ±t·Δt·|g|/2" : "", t, power_law(t, 0.5 * h * g), look::prediction);
    lines.line("", t, power_law(t, -0.5 * h * g), look::prediction);
  }
  return figure;
}

/// Log-log errors against Δt after one step (slope 2) and at T (slope 1), on the predictions.
inline Figure orders_figure(const FreeFall& fall, double t_end, const EulerOrders& o) {
  const double g = std::abs(fall.g);
  const std::string red = look::explicit_euler, blue = look::implicit_euler;
  Figure figure("convergence", "Euler's order: error after one step ∝ Δt², error at a fixed time T ∝ Δt");
  auto& loglog = figure.panel("time step Δt [s]", "|x - x_{exact}| [m]");
  loglog.logx = loglog.logy = true;
  loglog.key = "bottom right";  // below both lines, which rise to the right: always empty
  const auto slope = [](const char* what, const Sweep& s) {
    return fmt::format("{}: slope {:.3f}", what, s.order());
  };
  const auto& dts = o.dt;
  for (const auto& [what, sweep, style] :
       {std::tuple{"explicit, at T", &o.global_explicit, red + " pt 7 ps 0.8"},
        {"implicit, at T", &o.global_implicit, blue + " pt 6 ps 1.6"},
        {"explicit, after one step", &o.local_explicit, red + " pt 5 ps 0.8"},
        {"implicit, after one step", &o.local_implicit, blue + " pt 4 ps 1.6"}})
    if (!sweep->dt.empty()) loglog.points(slope(what, *sweep), sweep->dt, sweep->error, style);
  loglog.line("predictions T·Δt·|g|/2 and Δt²·|g|/2", dts, power_law(dts, 0.5 * t_end * g), look::prediction);
  loglog.line("", dts, power_law(dts, 0.5 * g, 2), look::prediction);
  return figure;
}

/// The round-off sweep: |error| at T against Δt in double and float, with the truncation line.
inline Figure roundoff_figure(const FreeFall& fall, double t_end, const Roundoff& r) {
  const double g = std::abs(fall.g);
  Figure figure("roundoff", fmt::format("Shrinking Δt until round-off wins: explicit and implicit Euler at "
                                        "T = {} s",
                                        t_end));
  figure.width_in = 8.0;
  auto& sweep = figure.panel("time step Δt [s]", "|x_N - x_{exact}(T)| [m]");
  sweep.logx = sweep.logy = true;
  // Only the curves whose exercise is written (ex 1.1, ex 1.3) are drawn.
  Sweep bests;
  for (const auto& [name, curve, style] :
       {std::tuple{"explicit, double", &r.doubles, look::explicit_euler + " pt 7 ps 0.7"},
        {"explicit, double: round-off part", &r.roundoff_part, look::explicit_euler + " dt 3 pt 1"},
        {"explicit, float", &r.floats, look::single_precision + " lw 3 pt 5 ps 1.1"},
        {"implicit, float", &r.floats_implicit, look::implicit_euler + " dt 2 pt 6 ps 1.3"}}) {
    if (curve->dt.empty()) continue;
    sweep.add({name, curve->dt, curve->error, "linespoints", style});
    if (curve != &r.roundoff_part) bests.add(curve->dt[curve->best()], curve->error[curve->best()]);
  }
  const auto& d = r.doubles.dt.empty() ? r.floats_implicit : r.doubles;
  sweep.line("truncation alone, T·Δt·|g|/2", d.dt, power_law(d.dt, 0.5 * t_end * g), look::prediction);
  sweep.points("best Δt of each curve", bests.dt, bests.error, look::highlight + " lw 2 pt 8 ps 2.5");
  return figure;
}

}  // namespace kit
