// Chapter 2: stability of a mass on a spring (lecture, "Masses ressorts", "Précision/Stabilité").
// On an undamped spring, explicit Euler grows by sqrt(1 + ω²Δt²) every step, for every Δt (ERRATA
// item 4); implicit Euler shrinks by the inverse, for every Δt (item 5); symplectic Euler stays
// bounded while Δt < 2/ω (item 7). With damping, explicit Euler is stable iff Δt < μ/K (item 6).
// Each critical step is measured by bisection on long runs and printed beside theory.
#include <kit/ode/step_count.hpp>
#include "spring_figures.hpp"
#include "spring_flags.hpp"
#include "spring_report.hpp"

namespace {
using kit::Scheme;

struct Setup {
  kit::Spring spring;                               // m = 1 kg, K = 100 N/m, μ = 0, L0 = 1 m
  kit::Vec2 u0{1.5, 0.0};                           // x0 [m], v0 [m/s]
  double dt = 0.02, t_end = 2.0;                    // [s]
  long n = 0;                                       // steps of dt over [0, t_end]
  kit::Written written;                             // the schemes, and R(z), whose exercises are written
  double h() const { return spring.omega() * dt; }  // ω·Δt; below, the spectral radius of one step at Δt
  double zeta() const { return spring.damping_ratio(); }
  kit::ReportValue radius(Scheme x) const { return kit::spectral_radius(written, x, h(), zeta()); }  // or "-"
};

// 1. The system u' = A u + b: its frequency, damping ratio and eigenvalues.
void the_system(kit::Report& report, Setup& s) {
  s.n = kit::require_whole_steps(s.t_end, s.dt, 1'000'000);
  kit::require_motion(s.spring, s.u0);
  kit::say_spring_system(report, s.spring, s.u0, s.dt, s.n);
  s.written = kit::written_parts(report, s.spring, s.u0, s.dt);  // names each part still waiting
}

// 2. Every scheme at Δt against the closed form (which GSL cross-checks). A diverged run ends
// before T: its last finite state says nothing about E(T) or the growth, so those are "-".
kit::SpringRuns every_scheme(kit::ChapterApp& app, const Setup& s) {
  const auto runs = kit::run_every_scheme(s.spring, s.u0, s.dt, s.n, s.written.schemes);
  const double zeta = s.spring.damping_ratio(), exact = kit::spring_motion(s.spring, s.u0, s.t_end)[0];
  const std::string factor = kit::factor_format(kit::largest_factor(runs, s.h(), zeta, s.written.factors));
  auto table = app.report().table("runs", kit::run_columns(factor));
  for (const auto& [scheme, run] : runs) {
    const std::string status = run.diverged() ? run.trajectory.divergence->describe() : "finished";
    if (run.diverged()) app.diverged(kit::name(scheme), status);
    const bool diverged = run.diverged();  // a lambda may not capture a structured binding in clang 14
    const auto finished = [diverged](double v) { return diverged ? kit::ReportValue{} : v; };
    const double x = run.trajectory.u.back()[0];
    table.row(kit::key(scheme), {std::string(kit::name(scheme)), finished(x), finished(std::abs(x - exact)),
                                 finished(run.energy_ratio), finished(run.growth), s.radius(scheme), status,
                                 finished(run.max_drift), run.steps(), run.diverged()});
  }
  table.print();
  app.report().say("",
                   "growth/step = (E_N/E_0)^(1/2N); exact for explicit Euler when undamped: sqrt(1 + "
                   "(ω·dt)²) = {explicit_undamped_growth" +
                       factor.substr(1) + "\n",
                   {{"explicit_undamped_growth", std::sqrt(1 + s.h() * s.h())}});
  const auto gsl = app.report().attempt("GSL cross-check", [&] {  // GSL runs the student's A, b (ex 2.1)
    return kit::gsl_cross_check(s.spring, s.u0, s.dt, s.n);
  });
  if (gsl) app.report().say("", gsl->sentence(), gsl->fields());
  return runs;
}

// 3. Critical steps ("Conditionnellement stable"), measured by bisection beside theory.
void critical_steps(kit::Report& report, const Setup& s) {
  report.print("\nCritical steps (bisection on long runs; above them the motion grows without bound):\n");
  auto table = report.table("critical", kit::critical_columns());
  for (const auto& c : kit::textbook_critical_cases(s.spring, s.written)) {
    const kit::Critical dt = kit::critical_step(c.scheme, c.spring);
    table.row(kit::key(c.scheme), {std::string(kit::name(c.scheme)), c.spring.damping,
                                   c.spring.damping_ratio(), dt.measured, dt.analytic, std::string(c.formula),
                                   c.closed_form, (dt.measured - c.closed_form) / c.closed_form});
  }
  table.print();
  report.print("On this spring as given:");
  for (Scheme scheme : s.written.schemes) {
    const kit::Critical dt = kit::critical_step(scheme, s.spring, 2'000'000);  // shorter runs: printed only
    report.say(std::string("limits_as_given/") + kit::key(scheme),
               fmt::format("  {}: {};", kit::name(scheme), kit::limit_text(dt.analytic)),
               {{"analytic", dt.analytic}, {"measured", dt.measured}});
  }
  report.print("\n");
}

// 4. Implicit Euler ("Inconditionnellement stable"): stable, and it damps the motion away.
void implicit_damping(kit::Report& report, const Setup& s) {
  report.print("\nImplicit Euler damps the motion away as ω·Δt grows (undamped spring; -: a period of the "
               "motion is shorter than one step):\n");
  auto table = report.table("implicit_damping", kit::implicit_damping_columns());
  for (double h : {0.01, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0}) {
    const double kept = kit::implicit_amplitude_per_step(s.spring, s.u0, h), predicted = 1 / std::hypot(1, h);
    table.row({h, kept, predicted, kit::per_period(kept, h), kit::per_period(predicted, h)});
  }
  table.print();
}

// 5. Extremes ("Ressorts raides: K grand ⇒ stiff"): what 1000 steps of Δt do to each scheme.
void stiff_springs(kit::Report& report, const Setup& s) {
  auto amplitudes = report.table("extremes_amplitude",
                                 kit::scheme_columns(kit::extremes_columns(), s.written.schemes, "×{:.3g}"));
  auto divergences = report.table("extremes", kit::scheme_columns({{"spring", ""}}, s.written.schemes));
  for (const auto& row : kit::measure_extremes(s.spring, s.u0, s.dt, 1000, s.written.schemes)) {
    amplitudes.row(row.label, row.amplitudes);
    divergences.row(row.label, row.divergences);
  }
  report.say("parameters",
             "\nExtremes, 1000 steps of dt = {dt} s: the amplitude after them, sqrt(E/E0), as a"
             " multiple of the start\n(-: diverged, |u| passed 1e8 times the starting distance from rest):\n",
             {{"dt", s.dt}});
  amplitudes.print();
  report.print("The step at which each run diverged (-: it ran all 1000 steps):\n");
  divergences.print();
}

// 6. The figures (none under --no-plot): positions, phase, energy, |R| against ω·Δt, regions, map.
void figures(kit::ChapterApp& app, const Setup& s, const kit::SpringRuns& runs) {
  if (app.options().no_plot) return;
  for (const auto& figure : kit::spring_figures(s.spring, s.u0, s.dt, s.t_end, runs, s.written))
    app.figure(figure);
}
}  // namespace

int main(int argc, char** argv) {
  Setup s;
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 2: stability of a mass on a spring");
  kit::add_spring_flags(app, s.spring, s.u0, 1e15);
  app.add_real("--dt", s.dt, "time step [s]", kit::positive(10.0));
  app.add_real("--t-end", s.t_end, "final time T [s], a whole number of steps", kit::positive(1e5));
  app.add_divergence_flag();
  return app.run(argc, argv, [&] {
    the_system(app.report(), s);  // it names what waits for an exercise; the rest runs what is written
    const auto runs = every_scheme(app, s);
    if (s.written.factors) app.section("critical steps", [&] { critical_steps(app.report(), s); });
    if (s.written.has(Scheme::implicit_euler)) implicit_damping(app.report(), s);
    stiff_springs(app.report(), s);
    figures(app, s, runs);
  });
}
