#include "continuum_report.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

namespace kit {

void print_material(Report& report, const FemMaterial& m) {
  const Lame lame = plane_stress_lame(m.young, m.poisson);
  report.say(
      "material",
      "1. The material: E = {young:g} Pa, ν = {poisson:g}, ρ = {density:g} kg/m³; in plane "
      "stress λ* = {lambda:.4g} Pa, μ = {mu:.4g} Pa. The cantilever ({length:g} m × {height:g} m) sags by "
      "{tip:.5g} mm at its tip by Euler–Bernoulli; its first bending mode is ω1 = {omega:.4g} rad/s.\n",
      {{"young", m.young},
       {"poisson", m.poisson},
       {"density", m.density},
       {"lambda", lame.lambda},
       {"mu", lame.mu},
       {"length", cantilever_length},
       {"height", cantilever_height},
       {"tip", 1e3 * euler_bernoulli_tip(m)},
       {"omega", cantilever_first_frequency(m)}});
}

void print_cantilever(Report& report, const std::map<FemModel, TipConvergence>& models,
                      const FemMaterial& material) {
  const double euler_bernoulli = euler_bernoulli_tip(material), timoshenko = timoshenko_tip(material);
  std::vector<Column> columns{{"cells through h", "ny"}, {"elements", "elements"}};
  for (const auto& [model, c] : models)
    columns.push_back({fmt::format("{} tip/EB − 1", model_name(model)), model_name(model), "{:+.5f}"});
  auto table = report.table("cantilever/meshes", columns);
  const auto& first = models.begin()->second.runs;
  for (std::size_t k = 0; k < first.size(); ++k) {
    std::vector<ReportValue> row{long(first[k].ny), first[k].elements};
    for (const auto& [model, c] : models) {
      ReportValue error;  // "-" where Newton failed
      if (c.runs[k].done) error = c.runs[k].error;
      row.push_back(error);
    }
    table.row(row);
  }
  table.print();
  report.say("cantilever",
             "Timoshenko's tip, shear included: {timoshenko:.5g} mm, {above:+.2f}% from "
             "Euler–Bernoulli's.\n",
             {{"timoshenko", 1e3 * timoshenko}, {"above", 100 * (timoshenko / euler_bernoulli - 1)}});
  const double sag = euler_bernoulli / cantilever_length;
  if (sag > 0.01)
    report.say("cantilever",
               "Euler–Bernoulli's tip is {sag:.3g} of the length: past small deflections, where it and "
               "the linear model hold; St Venant–Kirchhoff's answer is the large-rotation one.\n",
               {{"sag", sag}});
  std::optional<double> fem_limit;  // the 2-D answer, from a finite-element model that converged
  for (const auto& [model, c] : models)
    if (model != FemModel::springs && c.richardson.converges) fem_limit = c.richardson.limit;
  for (const auto& [model, c] : models) {
    const std::string section = fmt::format("cantilever/{}", model_name(model));
    const auto failed = std::find_if(c.runs.begin(), c.runs.end(), [](const TipRun& r) { return !r.done; });
    if (failed != c.runs.end()) {
      report.say(section, "{model}: Newton's method failed at {cells} cells through the height: {why}.\n",
                 {{"model", model_name(model)}, {"cells", long(failed->ny)}, {"why", failed->failure}});
      continue;
    }
    if (!c.richardson.converges) {
      report.say(
          section,
          "{model}: {finest:+.2f}% from Euler–Bernoulli at {elements} elements; the three finest meshes "
          "are not monotone (no Richardson limit of its own).\n",
          {{"model", model_name(model)},
           {"finest", 100 * c.runs.back().error},
           {"elements", c.runs.back().elements}});
      if (fem_limit)
        report.say(section,
                   "  That is {vs_fem:+.2f}% from the finite elements' limit: the springs settle "
                   "elsewhere than the 2-D answer.\n",
                   {{"vs_fem", 100 * (c.runs.back().tip / *fem_limit - 1)}});
      continue;
    }
    const double limit = c.richardson.limit;
    report.say(
        section,
        "{model}: {finest:+.2f}% from Euler–Bernoulli at {elements} elements; Richardson's limit "
        "{limit:.5g} mm is {vs_eb:+.2f}% from Euler–Bernoulli and {vs_timoshenko:+.2f}% from Timoshenko; "
        "the error falls as h^{order:.2f} (fitted from 2 cells through the height on; Richardson's ratio of "
        "the finest three says h^{richardson_order:.2f}).\n",
        {{"model", model_name(model)},
         {"finest", 100 * c.runs.back().error},
         {"elements", c.runs.back().elements},
         {"limit", 1e3 * limit},
         {"vs_eb", 100 * (limit / euler_bernoulli - 1)},
         {"vs_timoshenko", 100 * (limit / timoshenko - 1)},
         {"order", c.order},
         {"richardson_order", c.richardson.order}});
  }
}

void print_turns(Report& report, const std::vector<TurnedElement>& sweep) {
  auto table = report.table("turns", {{"turn [°]", "degrees", "{:.0f}"},
                                      {"|ε| (small)", "cauchy_strain", "{:.3g}"},
                                      {"|E| (Green)", "green_strain", "{:.1e}"},
                                      {"linear force / 1% stretch", "linear_force", "{:.3g}"},
                                      {"StVK force / 1% stretch", "stvk_force", "{:.1e}"}});
  for (const auto& t : sweep) {
    const bool shown = std::fmod(t.degrees + 1e-9, 30.0) < 1e-6;
    table.append("rows", {t.degrees, t.cauchy_strain, t.green_strain, t.linear_force, t.stvk_force}, shown);
  }
  table.print();
}

void print_plate(Report& report, const std::map<FemModel, PlateRun>& runs) {
  auto table = report.table("plate", {{"model", ""},
                                      {"h [s]", "h", "{:.3g}"},
                                      {"steps", "steps"},
                                      {"turned [rad]", "angle", "{:.4f}"},
                                      {"largest |E|", "strain", "{:.3g}"},
                                      {"energy change", "energy_change", "{:+.3g}"},
                                      {"", "diverged"},
                                      {"diverged at [s]", "diverged_at", "{:.3g}"}});
  for (const auto& [model, run] : runs) {
    ReportValue angle, strain, energy, when;  // "-" once the run has diverged: its last state is no result
    if (run.diverged) {
      when = run.diverged_at;
    } else {
      const PlateSample& end = run.samples.back();
      const double start = run.samples.front().energy;
      angle = end.angle;
      strain = end.strain;
      energy = (end.energy - start) / start;
    }
    table.row(model_name(model),
              {model_name(model), run.h, run.steps, angle, strain, energy, run.diverged, when});
  }
  table.print();
}

void print_stretch(Report& report, const std::map<FemModel, std::vector<StretchRow>>& rows) {
  auto table = report.table("stretch", {{"model", "model"},
                                        {"cells n", "n"},
                                        {"regular", "regular", "{:.5f}"},
                                        {"irregular", "irregular", "{:.5f}"},
                                        {"|difference|", "difference", "{:.2e}"}});
  for (const auto& [model, list] : rows)
    for (const auto& r : list)
      table.row({model_name(model), long(r.n), optional_value(r.regular), optional_value(r.irregular),
                 optional_value(r.difference())});
  table.print();
}

void print_trade(Report& report, const std::vector<std::vector<TipRun>>& series) {
  auto table = report.table("trade", {{"model", "model"},
                                      {"solver", "solver"},
                                      {"elements", "elements"},
                                      {"tip/EB − 1", "error", "{:+.4f}"},
                                      {"wall [s]", "seconds", "{:.3g}"},
                                      {"steps", "steps"},
                                      {"PCG iterations", "iterations"},
                                      {"", "note"}});
  for (const auto& list : series)
    for (const auto& r : list)
      table.row({model_name(r.model), solver_name(r.solver), r.elements,
                 r.done ? ReportValue(r.error) : ReportValue(),
                 r.done ? ReportValue(r.seconds) : ReportValue(), r.steps, r.iterations, r.failure});
  table.print();
}

}  // namespace kit
