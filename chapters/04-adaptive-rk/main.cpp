// Chapter 4: adaptive Runge–Kutta (lecture, "Calcul automatique du pas de temps", and the
// tableau it labels "Dormand-Prince (ode45)"). The tableaus checked, Cash–Karp correctly named
// and its sign fixed (ERRATA items 8–9); one run in detail; the lecture's step doubling, guarded
// against the endless loop it can fall into (item 10); a work-precision diagram against GSL and
// Boost.Odeint run in the same process; and stiffness, where stability holds the step down.
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <kit/app/chapter_app.hpp>
#include <kit/ode/butcher_tableau.hpp>
#include <kit/ode/run_fields.hpp>
#include <kit/ode/work_precision.hpp>
#include <kit/problems/orbit_problem.hpp>

#include "adaptive_figures.hpp"
#include "adaptive_report.hpp"
#include "adaptive_rk_methods.hpp"
#include "van_der_pol_stiffness.hpp"
#include "work_precision_report.hpp"

namespace {
using Run = kit::NamedRun<4>;
using Curves = std::vector<kit::WorkCurve>;

// 1. The tableaus, checked in long double: row sums and order conditions (ERRATA items 8–9).
void tableaus_checked(kit::Report& report) {
  report.print("Butcher tableaus, checked in long double (order conditions up to order 5):\n");
  auto table = report.table("tableaus", kit::tableau_columns());
  using kit::Nodes;
  for (const auto* t :
       {&kit::cash_karp(), &kit::cash_karp_as_printed(), &kit::dormand_prince(), &kit::bogacki_shampine()}) {
    const auto order = [&](const auto& b, Nodes nodes) { return long(kit::satisfied_order(*t, b, nodes)); };
    table.row({t->name, long(t->stages()), t->fsal, double(kit::row_sum_defect(*t)),
               order(t->b, Nodes::printed), order(t->b_hat, Nodes::printed), order(t->b, Nodes::row_sums),
               order(t->b_hat, Nodes::row_sums)});
  }
  table.print();
}

// 2. One run in detail: where it steps, what it rejects, what it costs.
Run one_run_in_detail(kit::Report& report, const kit::OrbitProblem& p, kit::DetailedMethod method,
                      const kit::EmbeddedOptions& o) {
  Run detail = kit::detailed_run(method, p.f, 0.0, p.y0, p.t_end, o);
  auto fields = kit::run_fields(detail.run, p.reference);
  const std::string note = detail.run.message.empty() ? "" : ": " + detail.run.message;
  fields.insert(fields.end(), {{"method", detail.name},
                               {"problem", p.name},
                               {"rtol", o.rtol},
                               {"atol", o.atol},
                               {"h0", o.h0},
                               {"note", note}});
  report.say("detail",
             "\n{method} on {problem} (rtol = {rtol}, atol = {atol}, h0 = {h0}): {rhs_evals} "
             "evaluations, {accepted} accepted and {rejected} rejected steps, max |y(T) - reference| = "
             "{error:.3g}; {status}{note}\n",
             fields);
  return detail;
}

// 3. The lecture's step doubling with explicit Euler (p = 1), as written and guarded (ERRATA item 10).
void step_doubling_and_its_trap(kit::Report& report, const kit::OrbitProblem& p, double e_min, double e_max,
                                double h0) {
  report.say("step_doubling",
             "\nStep doubling with explicit Euler, E_min = {e_min}, E_max = {e_max} "
             "(E_max/E_min = {ratio:.3g}; halving dt divides e by ~2^(p+1) = {factor}):\n",
             {{"e_min", e_min}, {"e_max", e_max}, {"ratio", e_max / e_min}, {"factor", 4L}});
  kit::StepDoubling options;
  options.e_min = e_min, options.e_max = e_max, options.dt0 = h0, options.max_steps = 2'000'000;
  for (bool guarded : {false, true}) {
    options.guarded = guarded;
    const auto run = kit::counted_step_doubling(kit::DoublingBase::euler, p.f, 0.0, p.y0, p.t_end, options);
    const std::string what = run.status != kit::RunStatus::finished
                                 ? "{status}: {message}\n"
                                 : "{status}: {accepted} accepted, {rejected} rejected, {evaluations} "
                                   "evaluations, error {error:.3g}"
                                   "\n";
    report.say(guarded ? "step_doubling/guarded" : "step_doubling/lecture",
               (guarded ? "  guarded (accept e <= E_max): " : "  the lecture's loop: ") + what,
               kit::run_fields(run, p.reference, "evaluations"));
  }
}

// 4. Work against precision: every method on the same problem, in the same process, one harness.
Curves work_against_precision(kit::ChapterApp& app, const kit::OrbitProblem& p, double h0) {
  const kit::WorkTiming timing;  // every run takes a turn in each round; its time is its fastest
  const auto methods = kit::all_work_methods(app.report(), p.f, 0.0, p.y0, p.t_end, h0);  // those written
  const Curves curves = kit::measure_work_precision(methods, p.reference, timing);
  app.report().say(
      "work_precision_timing",
      "\nWork against precision on {problem} (tolerance = rtol = atol; "
      "fixed RK4: the number of steps; time: fastest of {rounds} interleaved rounds):\n",
      {{"problem", p.name}, {"rounds", long(timing.rounds)}, {"min_seconds", timing.min_seconds}});
  kit::report_work_precision(app.report(), "work_precision", curves);
  return curves;
}

// 5. Stiffness: Van der Pol at large μ, where stability, not accuracy, holds the step down.
kit::StiffnessRun stiffness(kit::Report& report, double mu) {
  kit::StiffnessRun s = kit::van_der_pol_stiffness(report, mu, kit::chapter_dopri5());  // estimate first
  kit::say_van_der_pol(report, s);
  return s;
}

// 6. The figures of every section that ran.
void figures(kit::ChapterApp& app, const kit::OrbitProblem& p, const std::optional<Run>& detail,
             const kit::EmbeddedOptions& o, const Curves& curves, const std::optional<kit::StiffnessRun>& s) {
  if (detail) app.figure(kit::orbit_figure(p, detail->run, detail->name, detail->look, o.rtol, o.atol));
  if (detail) app.figure(kit::step_size_figure(p, detail->run, detail->name, detail->look));
  app.figure(kit::work_figure(curves, p, false));
  app.figure(kit::work_figure(curves, p, true));
  if (s) app.figure(kit::stiffness_figure(*s));
}
}  // namespace

int main(int argc, char** argv) {
  double rtol = 1e-6, atol = 1e-6, h0 = 1e-4, e_min = 4e-7, e_max = 1e-6, mu = 100.0, eccentricity = 0.6;
  std::string problem = "arenstorf", method = "dopri5";
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR,
                      "Chapter 4: adaptive Runge-Kutta against GSL and Boost.Odeint");
  app.add_choice("--problem", problem, "arenstorf (orbit, T = 17.07) or kepler (ellipse, T = 2π)",
                 kit::orbit_names.flags());
  app.add_choice("--method", method,
                 "the detailed run: dopri5 (production), cash-karp or bogacki-shampine "
                 "(general driver)",
                 kit::detailed_method_names.flags());
  app.add_real("--rtol", rtol, "relative tolerance of the detailed run", kit::between(1e-13, 1e-1));
  app.add_real("--atol", atol, "absolute tolerance of the detailed run, units of y",
               kit::between(1e-13, 1e-1));
  app.add_real("--h0", h0, "first trial step [time units]", kit::between(1e-10, 1.0));
  app.add_real("--emin", e_min, "step doubling: double dt below this error", kit::between(1e-14, 1.0));
  app.add_real("--emax", e_max, "step doubling: halve dt above this error", kit::between(1e-14, 1.0));
  app.add_real("--eccentricity", eccentricity, "Kepler orbit eccentricity e", kit::between(0.0, 0.95));
  app.add_real("--mu", mu, "Van der Pol nonlinear damping μ (stiff when large)", kit::between(0.1, 1e4));
  return app.run(argc, argv, [&] {
    if (!(e_min < e_max)) throw kit::UsageError(fmt::format("--emin {} must be < --emax {}", e_min, e_max));
    const kit::OrbitProblem p = kit::orbit_problem(kit::orbit_names.parse(problem).value(), eccentricity);
    const kit::DetailedMethod detailed = kit::detailed_method_names.parse(method).value();
    const kit::EmbeddedOptions options{rtol, atol, h0, 5'000'000};
    tableaus_checked(app.report());  // each section runs once its exercises (4.1–4.3) are written
    const auto detail =
        app.section("one run", [&] { return one_run_in_detail(app.report(), p, detailed, options); });
    app.section("step doubling", [&] { step_doubling_and_its_trap(app.report(), p, e_min, e_max, h0); });
    const auto curves = app.section("work-precision", [&] { return work_against_precision(app, p, h0); });
    const auto vdp = app.section("stiffness", [&] { return stiffness(app.report(), mu); });  // DOPRI5's
    if (!app.options().no_plot && curves) figures(app, p, detail, options, *curves, vdp);
  });
}
