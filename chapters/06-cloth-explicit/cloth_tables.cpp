// Chapter 6's tables (cloth_tables.hpp).
#include "cloth_tables.hpp"

namespace kit {

void print_stability_table(Report& report, const std::vector<StabilityCase>& cases) {
  auto table = report.table("stability", {{"springs", "layout"},
                                          {"integrator", "integrator"},
                                          {"ω_max [rad/s]", "omega_max", "{:.5g}"},
                                          {"predicted [s]", "predicted", "{:.4e}"},
                                          {"measured [s]", "measured", "{:.4e}"},
                                          {"measured/predicted", "ratio", "{:.4f}"}});
  for (const auto& c : cases) {
    const double measured = c.result.measured.estimate();
    table.row({c.layout, flag_name(c.integrator), c.result.omega_max, c.result.predicted, measured,
               c.result.predicted > 0 ? ReportValue(measured / c.result.predicted) : ReportValue{}});
  }
  table.print();
}

void print_resolution_table(Report& report, const std::vector<StabilityAtResolution>& sweep) {
  // (N − 1)·Δt_max: the grid step is the side over N − 1 cells, so that is what stays constant.
  auto table = report.table("resolution", {{"N", "n"},
                                           {"springs", "springs"},
                                           {"2/ω_max [s]", "predicted", "{:.4e}"},
                                           {"Δt_max [s]", "dt_max", "{:.4e}"},
                                           {"(N−1)·Δt_max [s]", "cells_dt", "{:.4e}"},
                                           {"spring forces per simulated s", "per_second", "{:.3e}"}});
  for (const auto& r : sweep)
    table.row({long(r.n), r.springs, r.predicted, r.measured.estimate(), (r.n - 1) * r.measured.estimate(),
               r.spring_evaluations_per_second});
  table.print();
}

void print_integrator_table(Report& report, const ClothRuns& runs) {
  auto table = report.table("integrators", {{"integrator", "integrator"},
                                            {"steps", "steps"},
                                            {"spring forces", "spring_terms"},
                                            {"E(end) − E(0) [J]", "energy_change", "{:.4g}"},
                                            {"peak stretch [%]", "peak_strain", "{:.3g}"},
                                            {"exploded at [s]", "exploded_at", "{:.4g}"}});
  for (const auto& [integrator, rec] : runs)
    table.row({flag_name(integrator), rec.steps, rec.work.spring_terms,
               rec.samples.back().total() - rec.samples.front().total(), 100 * rec.peak_strain,
               rec.exploded_at >= 0 ? ReportValue(rec.exploded_at) : ReportValue{}});
  table.print();
}

void print_mesh_table(Report& report, const std::map<Hanging, std::vector<Sag>>& sags) {
  auto table = report.table("mesh", {{"held", "hanging"},
                                     {"N", "n"},
                                     {"drop [mm]", "drop_mm", "{:.3f}"},
                                     {"peak stretch [%]", "peak_strain", "{:.3g}"},
                                     {"steps to rest", "steps"},
                                     {"at rest", "settled"}});
  for (const auto& [hanging, curve] : sags)
    for (const Sag& s : curve)
      table.row({describe(hanging), long(s.n), 1e3 * s.drop, 100 * s.peak_strain, s.steps, s.settled});
  table.print();
}

}  // namespace kit
