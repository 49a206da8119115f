#include <kit/rigid_report.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace kit {

std::vector<RotationIntegrator> available_rotation_integrators(Report& report, const RigidKernels& kernels,
                                                               const RigidShape& shape) {
  std::vector<RotationIntegrator> available;
  for (RotationIntegrator integrator : rotation_integrators()) {
    RigidState probe = spinning_state(shape, Vec3::Zero(), Vec3(1, 1, 1));
    if (report.attempt(display_name(integrator), [&] { rotation_step(kernels, integrator, shape, probe, 1e-3); }))
      available.push_back(integrator);
  }
  return available;
}

void print_drift_table(Report& report, const std::vector<RotationRun>& runs, double closed_form_interval) {
  auto table = report.table("integrators", {{"integrator", ""}, {"flips", "flips"},
                                            {"between flips [s]", "flip_interval", "{:.4f}"},
                                            {"vs closed form", "interval_error", "{:+.2g}"},
                                            {"max |ΔE|/E", "energy_drift", "{:.2g}"},
                                            {"max |Δ|L||/|L|", "momentum_drift", "{:.2g}"},
                                            {"max ‖RᵀR − I‖", "orthonormality", "{:.1g}"}});
  for (const auto& run : runs) {
    const double interval = run.flip_interval();
    const ReportValue error = std::isfinite(interval) ? ReportValue(interval / closed_form_interval - 1)
                                                      : ReportValue(std::monostate{});
    table.row(flag_name(run.integrator),
              {display_name(run.integrator), long(run.flip_times.size()),
               std::isfinite(interval) ? ReportValue(interval) : ReportValue(std::monostate{}), error,
               run.max_energy_drift, run.max_momentum_drift, run.max_orthonormality});
  }
  table.print();
}

void print_flip_sweep(Report& report, const std::vector<FlipSweepRow>& rows, double closed_form_interval) {
  auto table = report.table("flip_sweep", {{"integrator", "integrator"}, {"h [s]", "h", "{:.0e}"},
                                           {"flips", "flips"}, {"between flips [s]", "interval", "{:.4f}"},
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
  auto table = report.table("axes", {{"spin about", "axis"}, {"moment [kg·m²]", "moment", "{:.3e}"},
                                     {"largest tilt of ω [°]", "max_deviation_deg", "{:.3g}"},
                                     {"reversals", "flips"}, {"", "intermediate"}});
  for (const auto& spin : spins)
    table.row({names[spin.axis], spin.moment, spin.max_deviation_deg, spin.flips_about_axis,
               spin.axis == intermediate});
  table.print();
}

void print_trade(Report& report, const RotationTrade& trade) {
  auto table = report.table("trade", {{"integrator", "integrator"}, {"steps", "steps"}, {"h [s]", "h", "{:.1e}"},
                                      {"‖R − R_ref‖", "error", "{:.2e}"}, {"wall [ms]", "timing_ms", "{:.3g}"}});
  for (const auto& [integrator, curve] : trade.curves)
    for (const auto& p : curve)
      table.row({flag_name(integrator), p.steps, p.h, p.error, 1e3 * p.seconds});
  table.print();
}

void print_drop(Report& report, const std::string& section, const std::string& what, const DropRun& run,
                const GroundContact& contact, double drop_height, double resting) {
  const double first_rise = run.apexes.empty() ? 0.0 : (run.apexes.front() - resting) / drop_height;
  const DropSample& end = run.samples.back();
  report.say(section, "{what}: {bounces} bounces in {contacts} steps of contact; the first rises {rise:.4f} of the "
             "fall (e² = {e2:.4f}); deepest corner {deepest:.2e} m inside the ground within a step, {after:.1e} m "
             "after its contact; friction {friction:.3g} N·s; at most {gain:.1e} J gained across a contact, "
             "{sweeps} Gauss–Seidel sweeps at most; at the end, {kinetic:.2e} J of motion left, the centre at "
             "{height:.4f} m ({resting:.4f} m at rest).\n",
             {{"what", what}, {"bounces", long(run.bounces)}, {"contacts", long(run.contacts)},
              {"rise", first_rise}, {"e2", contact.restitution * contact.restitution}, {"deepest", -run.deepest},
              {"after", std::max(0.0, -run.deepest_after)}, {"friction", run.friction_impulse}, {"gain", run.largest_gain},
              {"sweeps", long(run.most_sweeps)}, {"kinetic", end.kinetic}, {"height", end.centre_height},
              {"resting", resting}});
  report.store(section, {{"total", end.total()}, {"start_total", run.samples.front().total()}});
}

}  // namespace kit
