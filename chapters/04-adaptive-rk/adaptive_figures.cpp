#include "adaptive_figures.hpp"

#include <algorithm>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <kit/app/look.hpp>

namespace kit {

namespace {
// v[0], v[stride], v[2·stride], …: what a figure draws of a long run.
std::vector<double> every(const std::vector<double>& v, std::size_t stride) {
  std::vector<double> out;
  for (std::size_t i = 0; i < v.size(); i += stride) out.push_back(v[i]);
  return out;
}
}  // namespace

Figure orbit_figure(const OrbitProblem& problem, const AdaptiveRun<Vec4>& run, const std::string& method,
                    const std::string& look, double rtol, double atol) {
  Figure figure("orbit", fmt::format("{}: {}'s accepted steps (rtol = {}, atol = {})", problem.title, method,
                                     rtol, atol));
  figure.width_in = 6.5, figure.height_in = 5.5;
  auto& xy =
      figure.panel(fmt::format("x [{}]", problem.length_unit), fmt::format("y [{}]", problem.length_unit));
  xy.commands = {"set size ratio -1"};
  const Trajectory<Vec4> path = problem.path(2000);
  xy.line("reference path (GSL rk8pd)", path.component(0), path.component(1), look::reference + " lw 1");
  xy.points(fmt::format("accepted steps ({})", run.stats.steps), run.accepted.component(0),
            run.accepted.component(1), look + " pt 7 ps 0.5");
  if (problem.earth_and_moon)
    xy.points("Earth, Moon", {-Arenstorf::mu, 1 - Arenstorf::mu}, {0.0, 0.0},
              look::highlight + " pt 6 ps 2 lw 2");
  return figure;
}

Figure step_size_figure(const OrbitProblem& problem, const AdaptiveRun<Vec4>& run, const std::string& method,
                        const std::string& look) {
  Figure figure("step-sizes", method + "'s step size along the run: small where the orbit bends sharply");
  auto& panel =
      figure.panel(fmt::format("t [{}]", problem.time_unit), fmt::format("step h [{}]", problem.time_unit));
  panel.logy = true;
  const std::vector<double> starts(run.accepted.t.begin(),
                                   run.accepted.t.end() - 1);  // where each step began
  panel.add({"accepted", starts, run.step_sizes, "linespoints", look + " pt 7 ps 0.4"});
  panel.points(fmt::format("rejected ({})", run.rejected_t.size()), run.rejected_t, run.rejected_h,
               look::highlight + " pt 2 ps 1.2 lw 2");
  return figure;
}

Figure work_figure(const std::vector<WorkCurve>& curves, const OrbitProblem& problem, bool by_time) {
  Figure figure(by_time ? "work-precision-timing" : "work-precision",
                fmt::format("{} ({})",
                            by_time ? "Error reached against wall time (this machine, this run)"
                                    : "Error reached against right-hand-side evaluations",
                            problem.name));
  figure.width_in = 8;
  auto& panel =
      figure.panel(by_time ? "wall time [s]" : "right-hand-side evaluations", "max |y(T) - reference|");
  panel.logx = panel.logy = true;
  for (const WorkCurve& c : curves) {
    std::vector<double> error = c.errors();
    for (double& e : error) e = std::max(e, 1e-16);  // a log axis has no 0
    panel.add({c.label, by_time ? c.seconds() : c.evaluations(), error, "linespoints", c.look});
  }
  return figure;
}

Figure stiffness_figure(const StiffnessRun& s) {
  const AdaptiveRun<Vec2>& run = s.run;
  const std::size_t stride = std::max<std::size_t>(1, run.step_sizes.size() / 20'000 + 1);
  std::vector<std::string> notes;
  if (s.adapted) notes.push_back(fmt::format("up to t = {:.4g}, the step budget", s.horizon));
  if (stride > 1) notes.push_back(fmt::format("1 step in {} drawn", stride));
  const std::string note = notes.empty() ? "" : fmt::format(" ({})", fmt::join(notes, "; "));
  Figure figure(
      "van-der-pol",
      fmt::format("Van der Pol, μ = {}{}: the explicit step is held down by stability", s.mu, note));
  figure.height_in = 5.5;
  auto& xs = figure.panel("t (time units)", "x");
  xs.place = {{0, 0.48, 1, 0.44}};
  xs.line("x(t)", every(run.accepted.t, stride), every(run.accepted.component(0), stride), look::highlight);
  auto& vh = figure.panel("t (time units)", "step h (time units)");
  vh.place = {{0, 0.0, 1, 0.46}};
  vh.logy = true;
  const std::vector<double> starts(run.accepted.t.begin(), run.accepted.t.end() - 1);
  vh.points(fmt::format("accepted ({})", run.stats.steps), every(starts, stride),
            every(run.step_sizes, stride), look::dopri5 + " pt 7 ps 0.3");
  vh.points(fmt::format("rejected ({})", run.stats.rejected), run.rejected_t, run.rejected_h,
            look::highlight + " pt 2 ps 0.8");
  figure.left_edge = 0.08, figure.right_edge = 0.78;
  return figure;
}

}  // namespace kit
