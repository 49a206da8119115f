// Chapter 7's tables (cloth_implicit_tables.hpp).
#include "cloth_implicit_tables.hpp"

#include <fmt/format.h>

namespace kit {

void print_stiffness_table(Report& report, const std::vector<StiffnessRow>& rows, double h) {
  auto table = report.table("stiffness", {{"K [N/m]", "stiffness", "{:.0e}"},
                                          {"symplectic Δt_max [s]", "dt_max", "{:.3e}"},
                                          {"2/ω_max [s]", "predicted", "{:.3e}"},
                                          {"steps per 1/30 s", "steps_per_frame", "{:.3g}"},
                                          {"method at h", "method"},
                                          {"stable", "stable"},
                                          {"E(end) − E(0) [J]", "energy_change", "{:.3e}"},
                                          {"max E − E(0) [J]", "peak_gain", "{:.3e}"},
                                          {"largest rise in a step [J]", "largest_rise", "{:.3e}"},
                                          {"steps it rose", "rising_steps"},
                                          {"iterations", "iterations"},
                                          {"failure", "failure"}});
  for (const auto& r : rows)
    for (const auto& s : r.implicit)
      table.row({r.stiffness, r.measured.estimate(), r.predicted, (1.0 / 30) / r.measured.estimate(),
                 fmt::format("{} ({:.3g} s)", flag_name(s.method), h), s.stable, s.energy_change, s.peak_gain,
                 s.largest_rise, s.rising_steps, s.iterations, s.failure});
  table.print();
}

void print_trade_table(Report& report, const Trade& trade) {
  auto table = report.table("trade", {{"method", "method"},
                                      {"Δt [s]", "dt", "{:.3e}"},
                                      {"iterations", "iterations"},
                                      {"RMS error [m]", "error", "{:.3e}"},
                                      {"energy removed [J]", "energy_lost", "{:.3e}"},
                                      {"wall time [s]", "seconds", "{:.3e}"},
                                      {"failed", "failed"}});
  for (const auto& r : trade.runs)
    table.row({r.key, r.dt, long(r.iterations), r.error, r.energy_lost, r.seconds, r.failed});
  table.print();
  report.say("damping_scale",
             "The swing's largest kinetic energy before t = {t_end} s (the reference, from rest): "
             "{motion_energy:.3e} J, the scale of the energy a method removes.\n",
             {{"t_end", trade.t_end}, {"motion_energy", trade.energy_scale}});
}

void print_solver_table(Report& report, const std::vector<SolverPoint>& points) {
  auto table = report.table("solver", {{"solver", "solver"},
                                       {"K [N/m]", "stiffness", "{:.0e}"},
                                       {"h [s]", "h", "{:.4g}"},
                                       {"mean iterations", "mean_iterations", "{:.1f}"},
                                       {"most", "max_iterations"},
                                       {"unconverged", "unconverged"}});
  for (const auto& q : points)
    table.row({flag_name(q.solver), q.stiffness, q.h, q.mean_iterations, q.max_iterations, q.unconverged});
  table.print();
}

void print_implicit_work(Report& report, const ClothRecording& rec) {
  const ImplicitWork& w = rec.implicit;
  if (w.steps == 0 && rec.failure.empty()) return;
  report.say(
      "implicit_work",
      "Implicit steps: {steps}; linear solves {solves} ({cg} CG iterations, {mean:.1f} a solve, "
      "at most {most}; {unconverged} stopped at the cap); Newton solves {newton}; Liu iterations {liu}; "
      "{filtered} node-steps held on a collider inside the solve; {multigrid} multigrid set-ups.\n",
      {{"steps", w.steps},
       {"solves", w.solves},
       {"cg", w.cg_iterations},
       {"mean", w.solves ? double(w.cg_iterations) / double(w.solves) : 0.0},
       {"most", w.max_cg_iterations},
       {"unconverged", w.unconverged_solves},
       {"newton", w.newton_iterations},
       {"liu", w.local_global},
       {"filtered", w.filtered_nodes},
       {"multigrid", w.multigrid_setups}});
}

}  // namespace kit
