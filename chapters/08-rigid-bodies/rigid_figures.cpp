// Chapter 8's figures (rigid_figures.hpp).
#include "rigid_figures.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <kit/app/look.hpp>

namespace kit {
namespace {

const char* axis_name(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

}  // namespace

std::string rigid_style(RotationIntegrator integrator) {
  switch (integrator) {
    case RotationIntegrator::euler_matrix:
      return look::explicit_euler;
    case RotationIntegrator::euler_polar:
      return "lc rgb '#ff7f0e'";
    case RotationIntegrator::euler_quaternion:
      return "lc rgb '#e377c2'";
    case RotationIntegrator::exponential_map:
      return look::implicit_euler;
    case RotationIntegrator::midpoint:
      return look::midpoint;
    default:
      return look::rk4;
  }
}

Figure rigid_flips_figure(const std::vector<RotationRun>& runs, const RigidShape& shape,
                          const std::vector<double>& reference_flips) {
  const int axis = intermediate_axis(shape);
  Figure fig("flips",
             fmt::format("The {}'s spin about its intermediate axis ({}) flips; dotted: the reference's "
                         "flips (GSL rk8pd)",
                         shape.name, axis_name(axis)));
  // Two columns, the lecture's steps on the left: readable on a 16:9 slide as on a page.
  fig.columns = 2;
  fig.width_in = 10;
  fig.height_in = 2.0 * double((runs.size() + 1) / 2) + 1.0;
  for (const auto& run : runs) {
    // One curve a panel: its name is the panel's title, and no legend covers the data.
    auto& p = fig.panel("time t [s]", fmt::format("ω_{} [rad/s]", axis_name(axis)),
                        fmt::format("{}, h = {:.3g} s: {} flips", display_name(run.integrator), run.h,
                                    run.flip_times.size()));
    p.key = "off";
    p.commands.push_back("set ytics 10");  // −10, 0, 10: a flat panel has room for three labels
    std::vector<double> t, w;
    for (const auto& s : run.samples) t.push_back(s.t), w.push_back(s.omega_body[axis]);
    p.line(display_name(run.integrator), t, w, rigid_style(run.integrator) + " lw 1.5");
    for (double f : reference_flips)
      p.commands.push_back(
          fmt::format("set arrow from {0},graph 0 to {0},graph 1 nohead {1}", f, look::guide));
    if (!t.empty()) p.commands.push_back(fmt::format("set xrange [0:{}]", t.back()));
  }
  return fig;
}

Figure rigid_drift_figure(const std::vector<RotationRun>& runs, const std::string& body) {
  Figure fig("drift", fmt::format("What each integrator keeps of the {}'s invariants (no torque: both are "
                                  "constant)",
                                  body));
  fig.height_in = 6;
  fig.left_edge = 0.12;
  fig.right_edge = 0.68;
  auto& energy = fig.panel("time t [s]", "|E − E_0| / E_0", "kinetic energy (at 10^{-17}: exact)");
  auto& momentum = fig.panel("time t [s]", "| |L| − |L_0| | / |L_0|",
                             "angular momentum in the world frame "
                             "(at 10^{-17}: exact)");
  for (auto* p : {&energy, &momentum}) {
    p->logy = true;
    p->commands.push_back("set format y '10^{%T}'");
    p->commands.push_back("set yrange [3e-18:*]");  // the exact ones' floor above the axis
  }
  // The three first-order steps that stay on SO(3) draw the same curves: dashed differently and
  // widest first, so that each one shows under the next.
  double width = 4.5;
  for (const auto& run : runs) {
    std::vector<double> t, e, l;
    for (const auto& s : run.samples)
      if (s.t > 0)
        t.push_back(s.t), e.push_back(magnitude_on_log_axis(s.energy_drift)),
            l.push_back(magnitude_on_log_axis(s.momentum_drift));
    const std::string style = rigid_style(run.integrator) + fmt::format(" lw {:g}", width);
    width = std::max(1.5, width - 1.0);
    energy.line(display_name(run.integrator), t, e, style);
    momentum.line(display_name(run.integrator), t, l, style);
  }
  return fig;
}

Figure rigid_orthonormality_figure(const std::vector<RotationRun>& runs, const std::string& body) {
  Figure fig("orthonormality", fmt::format("How far R leaves the rotations (the {} tumbling)", body));
  auto& p = fig.panel("time t [s]", "‖R^TR − I‖ (Frobenius)");
  p.logy = true;
  p.commands.push_back("set format y '10^{%T}'");
  for (const auto& run : runs) {
    std::vector<double> t, o;
    for (const auto& s : run.samples)
      if (s.t > 0) t.push_back(s.t), o.push_back(magnitude_on_log_axis(s.orthonormality));
    p.line(display_name(run.integrator), t, o, rigid_style(run.integrator) + " lw 1.5");
  }
  return fig;
}

Figure rigid_axes_figure(const std::vector<AxisSpin>& spins, const std::string& body) {
  Figure fig("axes", fmt::format("The {} spun at 10 rad/s about each principal axis, nudged by 0.1 rad/s "
                                 "(RK4, h = 1 ms)",
                                 body));
  fig.width_in = 10;
  fig.height_in = 4;
  fig.columns = int(spins.size());
  const char* which[] = {"smallest moment: stable", "intermediate: flips", "largest moment: stable"};
  const char* colours[] = {"#d62728", "#2ca02c", "#1f77b4"};
  for (std::size_t i = 0; i < spins.size(); ++i) {
    const AxisSpin& spin = spins[i];
    auto& p =
        fig.panel("time t [s]", "ω in the body frame [rad/s]",
                  fmt::format("about {} ({}, {:.2e} kg·m²)", axis_name(spin.axis), which[i], spin.moment));
    // The smallest axis's panel is empty between its steady spin (10) and zero: the legend goes there.
    p.key = i == 0 ? "at graph 0.97, graph 0.85 right top box opaque" : "off";
    p.commands.push_back("set yrange [-11:11]");
    for (int component = 0; component < 3; ++component) {
      std::vector<double> t, w;
      for (const auto& s : spin.run.samples) t.push_back(s.t), w.push_back(s.omega_body[component]);
      p.line(fmt::format("ω_{}", axis_name(component)), t, w,
             fmt::format("lc rgb '{}' lw 1.5", colours[component]));
    }
  }
  return fig;
}

Figure rigid_trade_figure(const RotationTrade& trade, const std::string& body) {
  Figure fig("trade-timing", fmt::format("What accuracy costs: the {}'s orientation after {:g} s against GSL "
                                         "rk8pd at 1e-13",
                                         body, trade.t_end));
  auto& p = fig.panel("wall time [s] (this machine, one run)", "‖R − R_{ref}‖ at T (Frobenius)");
  p.logx = p.logy = true;
  p.commands.push_back("set format x '10^{%T}'");
  p.commands.push_back("set format y '10^{%T}'");
  for (const auto& [integrator, curve] : trade.curves) {
    std::vector<double> seconds, error;
    for (const auto& point : curve)
      seconds.push_back(std::max(point.seconds, 1e-7)), error.push_back(magnitude_on_log_axis(point.error));
    p.add(
        {display_name(integrator), seconds, error, "linespoints", rigid_style(integrator) + " lw 1.5 pt 7"});
  }
  return fig;
}

Figure rigid_drop_figure(const std::string& name, const std::string& what, const DropRun& run,
                         const GroundContact& contact, double drop_height) {
  Figure fig(name, fmt::format("{} from {:g} m: e = {:g}, μ = {:g}", what, drop_height, contact.restitution,
                               contact.friction));
  fig.height_in = 6;
  fig.left_edge = 0.1;
  fig.right_edge = 0.97;
  auto& height = fig.panel("time t [s]", "height y [m] (up)", "height above the ground y = 0");
  auto& energy = fig.panel("time t [s]", "energy [J]", "energy (potential M g y_{centre})");
  // A drop comes to rest within 2 s: the top right of both panels is empty.
  height.key = energy.key = "top right box opaque";
  std::vector<double> t, centre, lowest, kinetic, total;
  for (const auto& s : run.samples) {
    t.push_back(s.t), centre.push_back(s.centre_height), lowest.push_back(s.lowest);
    kinetic.push_back(s.kinetic), total.push_back(s.total());
  }
  height.line("centre of mass", t, centre, look::implicit_euler + " lw 2");
  height.line("lowest corner (< 0: inside the ground)", t, lowest, look::explicit_euler + " lw 1.5");
  height.commands.push_back(
      fmt::format("set arrow from graph 0,first 0 to graph 1,first 0 nohead {}", look::guide));
  energy.line("kinetic", t, kinetic, look::symplectic_euler + " lw 1.5");
  energy.line("kinetic + potential", t, total, look::exact);
  return fig;
}

}  // namespace kit
