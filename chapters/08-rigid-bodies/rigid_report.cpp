#include "rigid_report.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace kit {

void print_body(Report& report, const RigidShape& shape, const Vec3& omega0, double interval) {
  const Vec3 moments = shape.principal_moments();
  const std::string closed_form =
      std::isfinite(interval)
          ? fmt::format("by the closed form, ω along the intermediate axis changes sign every {:.5f} s",
                        interval)
          : std::string("two of its principal moments are equal: no axis is intermediate, nothing flips");
  report.say("body",
             "1. The {body}, {mass:g} kg: principal moments {i1:.4e}, {i2:.4e}, {i3:.4e} kg·m². Started "
             "at ω = ({w}) rad/s in its body frame; {closed_form}.\n",
             {{"body", shape.name},
              {"mass", shape.mass},
              {"i1", moments[0]},
              {"i2", moments[1]},
              {"i3", moments[2]},
              {"w", fmt::format("{:g}, {:g}, {:g}", omega0[0], omega0[1], omega0[2])},
              {"closed_form", closed_form}});
  report.store("body", {{"interval", std::isfinite(interval) ? ReportValue(interval) : ReportValue()}});
}

void print_angular_velocity_check(Report& report, const RigidKernels& kernels, const RigidShape& shape) {
  const Mat3 R = Quat(0.6, 0.2, -0.7, 0.3).normalized().toRotationMatrix();  // any rotation
  const Vec3 L(0.3, -0.1, 0.2), direct = (R * shape.inertia * R.transpose()).inverse() * L;
  const double error =
      (kernels.angular_velocity(R, shape.inverse_inertia, L) - direct).norm() / direct.norm();
  report.say("omega", "Your ω = R I⁻¹ Rᵀ L (ex 8.3) differs from (R I Rᵀ)⁻¹ L by {error:.1e} (relative).\n",
             {{"error", error}});
}

std::vector<RotationIntegrator> available_rotation_integrators(Report& report, const RigidKernels& kernels,
                                                               const RigidShape& shape) {
  std::vector<RotationIntegrator> available;
  for (RotationIntegrator integrator : rotation_integrators) {
    RigidState probe = spinning_state(shape, Vec3::Zero(), Vec3(1, 1, 1));
    if (report.attempt(display_name(integrator),
                       [&] { rotation_step(kernels, integrator, shape, probe, 1e-3); }))
      available.push_back(integrator);
  }
  return available;
}

void print_drift_table(Report& report, const std::vector<RotationRun>& runs, double closed_form_interval) {
  auto table = report.table("integrators", {{"integrator", ""},
                                            {"flips", "flips"},
                                            {"between flips [s]", "flip_interval", "{:.4f}"},
                                            {"vs closed form", "interval_error", "{:+.2g}"},
                                            {"max |ΔE|/E", "energy_drift", "{:.2g}"},
                                            {"max |Δ|L||/|L|", "momentum_drift", "{:.2g}"},
                                            {"max |Δ|RᵀL||/|L|", "body_momentum_drift", "{:.2g}"},
                                            {"max ‖RᵀR − I‖", "orthonormality", "{:.1g}"},
                                            {"", "unconverged_steps"}});
  for (const auto& run : runs) {
    const double interval = run.flip_interval();
    const ReportValue error = std::isfinite(interval) ? ReportValue(interval / closed_form_interval - 1)
                                                      : ReportValue(std::monostate{});
    table.row(flag_name(run.integrator),
              {display_name(run.integrator), long(run.flip_times.size()),
               std::isfinite(interval) ? ReportValue(interval) : ReportValue(std::monostate{}), error,
               run.max_energy_drift, run.max_momentum_drift, run.max_body_momentum_drift,
               run.max_orthonormality, run.unconverged_steps});
  }
  table.print();
  for (const auto& run : runs)
    if (run.unconverged_steps > 0)
      report.print(
          fmt::format("{}: the fixed point stalled in {} of {} steps, each then split into halves.\n",
                      display_name(run.integrator), run.unconverged_steps, run.steps));
}

void print_flip_sweep(Report& report, const std::vector<FlipSweepRow>& rows, double closed_form_interval) {
  auto table = report.table("flip_sweep", {{"integrator", "integrator"},
                                           {"h [s]", "h", "{:.0e}"},
                                           {"flips", "flips"},
                                           {"between flips [s]", "interval", "{:.4f}"},
                                           {"vs closed form", "interval_error", "{:+.2g}"},
                                           {"max |ΔE|/E", "energy_drift", "{:.2g}"}});
  for (const auto& r : rows) {
    const bool flips = std::isfinite(r.interval);
    table.row({flag_name(r.integrator), r.h, r.flips, flips ? ReportValue(r.interval) : ReportValue(),
               flips ? ReportValue(r.interval / closed_form_interval - 1) : ReportValue(),
               r.diverged ? ReportValue("diverged") : ReportValue(r.max_energy_drift)});
  }
  table.print();
}

void print_axes(Report& report, const std::vector<AxisSpin>& spins, int intermediate) {
  const char* names[] = {"x", "y", "z"};
  auto table = report.table("axes", {{"spin about", "axis"},
                                     {"moment [kg·m²]", "moment", "{:.3e}"},
                                     {"largest tilt of ω [°]", "max_deviation_deg", "{:.3g}"},
                                     {"reversals", "flips"},
                                     {"", "intermediate"}});
  for (const auto& spin : spins)
    table.row({names[spin.axis], spin.moment, spin.max_deviation_deg, spin.flips_about_axis,
               spin.axis == intermediate});
  table.print();
}

void print_trade(Report& report, const RotationTrade& trade) {
  auto table = report.table("trade", {{"integrator", "integrator"},
                                      {"steps", "steps"},
                                      {"h [s]", "h", "{:.1e}"},
                                      {"‖R − R_ref‖", "error", "{:.2e}"},
                                      {"wall [ms]", "timing_ms", "{:.3g}"}});
  for (const auto& [integrator, curve] : trade.curves)
    for (const auto& p : curve)
      table.row({flag_name(integrator), p.steps, p.h,
                 std::isfinite(p.error) ? ReportValue(p.error) : ReportValue("diverged"), 1e3 * p.seconds});
  table.print();
}

void print_drop(Report& report, const std::string& section, const std::string& what, const DropRun& run,
                const GroundContact& contact, double drop_height, double resting) {
  const double first_rise = run.apexes.empty() ? 0.0 : (run.apexes.front() - resting) / drop_height;
  const DropSample& end = run.samples.back();
  const std::string flat = run.settled_at < end.t ? fmt::format("lies flat from {:.2f} s on", run.settled_at)
                                                  : std::string("is not lying flat at the end");
  report.say(section,
             "{what}: {bounces} bounces in {contacts} steps of contact; the first rises {rise:.4f} of the "
             "fall (e² = {e2:.4f}); deepest corner {deepest:.2e} m inside the ground within a step; friction "
             "{friction:.3g} N·s; the impulses added at most {impulse_gain:.1e} J of motion, a contact with "
             "its lift "
             "{gain:.1e} J; {sweeps} Gauss–Seidel sweeps at most ({unconverged} contacts stopped at the "
             "cap); it turned ‖R − R(0)‖ = {turn:.2e} at most (2√2: half a turn), and {flat}; at the "
             "end, {kinetic:.2e} J of motion left, the centre at {height:.4f} m ({resting:.4f} m at rest).\n",
             {{"what", what},
              {"bounces", long(run.bounces)},
              {"contacts", long(run.contacts)},
              {"rise", first_rise},
              {"e2", contact.restitution * contact.restitution},
              {"deepest", -run.deepest},
              {"friction", run.friction_impulse},
              {"impulse_gain", run.largest_impulse_gain},
              {"gain", run.largest_gain},
              {"sweeps", long(run.most_sweeps)},
              {"unconverged", long(run.unconverged_contacts)},
              {"turn", run.largest_turn},
              {"settled_at", run.settled_at},
              {"flat", flat},
              {"kinetic", end.kinetic},
              {"height", end.centre_height},
              {"resting", resting}});
  report.store(section, {{"total", end.total()}, {"start_total", run.samples.front().total()}});
}

void print_scene_runs(Report& report, RotationIntegrator integrator, double h, const RigidShape& shape,
                      double t_end, const RotationRun& tumble, const DropRun& drop) {
  report.say("scene",
             "\n6. With {integrator} at h = {h:.3g} s: the {body} tumbles {t:g} s and flips {flips} "
             "times, |ΔE|/E ≤ {energy:.2g}; the box dropped tilted 30° bounces {bounces} times.\n",
             {{"integrator", display_name(integrator)},
              {"h", h},
              {"body", shape.name},
              {"t", t_end},
              {"flips", long(tumble.flip_times.size())},
              {"energy", tumble.max_energy_drift},
              {"bounces", long(drop.bounces)}});
}

}  // namespace kit
