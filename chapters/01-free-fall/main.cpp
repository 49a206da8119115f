// Chapter 1: free fall with explicit and implicit Euler (lecture, "Chute libre").
// Both schemes miss the exact parabola by exactly k/2·Δt²·|g| after k steps (ERRATA item 1):
// explicit Euler above it, implicit Euler below it (y axis up, g < 0). The chapter checks that
// identity, measures local and global orders (ERRATA item 2), shrinks Δt until round-off wins,
// and prices each digit of accuracy.
#include <algorithm>

#include <fmt/format.h>

#include <kit/ode/step_count.hpp>

#include "euler_gap.hpp"
#include "free_fall_costs.hpp"
#include "free_fall_euler.hpp"
#include "free_fall_figures.hpp"
#include "free_fall_flags.hpp"
#include "free_fall_report.hpp"

namespace {
struct Setup {
  kit::FreeFall fall;    // x0 = 20 m, v0 = 0 m/s, g = −9.81 m/s² (y axis up)
  double dt = 0.1;       // [s]
  double t_end = 1.0;    // [s]
  double dt_min = 1e-9;  // [s], the smallest step asked of the round-off sweep
  long n = 0;            // steps of dt over [0, t_end]
};

// 1. The system u = (x, v): x' = v, v' = g, over n whole steps of Δt. Only the user's own
// parameters can be refused; the round-off sweep adapts to them (section 4).
void the_system(kit::Report& report, Setup& s) {
  s.n = kit::require_whole_steps(s.t_end, s.dt, 1'000'000);
  kit::require_measurable(s.fall, s.t_end, s.dt_min);
  kit::say_free_fall(report, s.fall, s.dt, s.n);
}

// 2. The lecture's loop (explicit Euler on f), both matrix forms and GSL's rk8pd, against the
// closed form: the error after k steps is k/2·Δt²·|g| (ERRATA item 1).
kit::EulerRuns loop_and_matrix_forms(kit::Report& report, const Setup& s) {
  const auto r = kit::run_euler(report, s.fall, s.dt, s.t_end);  // the methods whose exercise is written
  const auto& expl = r.explicit_run();                           // matrix form (ex 1.2), else loop (ex 1.1)
  const auto gap_expl = kit::gap(s.fall, expl), gap_impl = kit::gap(s.fall, r.impl);
  const auto check = kit::check_euler_gaps(s.fall, s.dt, s.t_end, gap_expl, gap_impl);
  auto table = report.table("samples", kit::sample_columns());
  const std::size_t samples = std::size_t(s.n) + 1, every = std::max<std::size_t>(1, samples / 10);
  for (std::size_t k = 0; k < samples; ++k)  // about ten rows; "-" where a method waits for its exercise
    if (k % every == 0 || k + 1 == samples)
      table.row({long(k), r.reference.t[k], s.fall.position(r.reference.t[k]), kit::height_at(expl, k),
                 kit::height_at(r.impl, k), kit::value_at(gap_expl, k), kit::value_at(gap_impl, k),
                 check.predicted[k], kit::value_at(check.match, k), kit::height_at(r.loop, k),
                 r.reference.u[k][0]});
  table.print();
  report.say("",
             "\nOver all {steps} steps, | |err| - k/2·Δt²·|g| | <= {max_prediction_mismatch:.3g} m; "
             "the loop and the matrix form differ by {loop_vs_matrix:.3g} m.\n",
             {{"steps", s.n},
              {"rhs_evals", kit::optional_value(r.loop_rhs_evals())},
              {"max_prediction_mismatch", kit::optional_value(check.checked_mismatch())},
              {"loop_vs_matrix", kit::optional_value(r.loop_vs_matrix())}});
  report.say("reference",
             "GSL rk8pd reference: max |x - exact| = {max_error:.3g} m, {rhs_evals} "
             "right-hand-side evaluations.\n",
             {{"max_error", r.reference_error(s.fall)}, {"rhs_evals", r.reference_stats.rhs_evals}});
  return r;
}

// 3. Orders (ERRATA item 2): the error after one step ∝ Δt², the error at a fixed time T ∝ Δt.
kit::EulerOrders orders(kit::Report& report, const Setup& s) {
  const auto o = kit::measure_orders(report, s.fall, s.t_end);
  report.json("convergence") = o.to_json();
  report.say("convergence",
             "\nObserved orders, least-squares slopes over dt = {dt_largest:.3g} .. "
             "{dt_smallest:.3g} s:\n  error at T = {t_end} s:     ",
             {{"t_end", s.t_end}, {"dt_largest", o.dt.front()}, {"dt_smallest", o.dt.back()}});
  report.say("convergence/slopes",
             "explicit {global_explicit:.4f}, implicit {global_implicit:.4f}  "
             "(global error, expected 1)\n  error after one step: explicit {local_explicit:.4f}, implicit "
             "{local_implicit:.4f}  (local error, expected 2)\n",
             o.slopes());
  return o;
}

// 4. The extreme: shrink Δt until round-off wins, in double and in float, and price each digit.
// Each run stays within a budget of steps; past it, the smallest Δt is raised, and it says so.
kit::Roundoff roundoff(kit::Report& report, const Setup& s) {
  const auto doubles = kit::budget_sweep(s.t_end, 0.1, s.dt_min, 2'000'000'000);
  const auto floats = kit::budget_sweep(s.t_end, 0.1, 1e-7, 100'000'000);  // float stagnates below 1e-7 s
  const std::vector<kit::Field> plan = kit::sweep_plan(doubles, floats);   // T, both Δt ranges, budgets
  report.store("roundoff/sweep", plan);
  kit::announce_roundoff(report, doubles, floats, kit::roundoff_costs(s.fall, s.t_end));  // or refuses
  if (doubles.raised() || floats.raised())
    report.say("roundoff/sweep",
               "\nThe round-off sweep takes at most {max_steps} steps a run "
               "({float_max_steps} in float):\nover T = {t_end} s, its smallest dt is {dt_min:.3g} s "
               "(--dt-min asked for {dt_min_requested:.3g} s), and {float_dt_min:.3g} s in float.\n",
               plan);
  const auto r = kit::measure_roundoff(report, s.fall, doubles, floats);
  if (!r.cost.empty())
    report.say("roundoff/sweep",
               "\nWhat accuracy costs (explicit Euler, double, T = {t_end} s): each digit "
               "costs 10x the steps\n",
               plan);
  auto cost = report.table("cost", kit::cost_columns());
  for (std::size_t i = 0; i < r.cost.size(); ++i) {  // every 4th run and the finest printed, all in the JSON
    const auto& c = r.cost[i];
    cost.row({c.dt, c.steps, c.rhs_evals, c.error, c.seconds, 1e9 * c.seconds / double(c.steps)},
             i % 4 == 0 || i + 1 == r.cost.size());
  }
  if (!r.cost.empty()) cost.print();
  report.print("\nWhere round-off wins (the error falls with dt, then rises again below the best dt):\n");
  auto wins = report.table("roundoff", kit::roundoff_columns());
  for (auto [key, curve, sweep] : {std::tuple{"explicit_double", "explicit, double", &r.doubles},
                                   {"explicit_float", "explicit, float", &r.floats},
                                   {"implicit_float", "implicit, float", &r.floats_implicit}}) {
    report.json(std::string("roundoff/") + key) = sweep->to_json();
    if (sweep->dt.empty()) continue;  // its exercise is not written yet
    const std::size_t best = sweep->best();
    wins.row(key, {std::string(curve), sweep->dt[best], sweep->error[best], sweep->dt.back(),
                   sweep->error.back()});
  }
  wins.print();
  report.json("roundoff/explicit_double")["roundoff_part"] = r.roundoff_part.error;
  return r;
}

// 5. The figures, each with its sign convention (not even computed under --no-plot).
void figures(kit::ChapterApp& app, const Setup& s, const kit::EulerRuns& runs, const kit::EulerOrders& o,
             const kit::Roundoff& r) {
  if (app.options().no_plot) return;
  app.figure(kit::trajectories_figure(s.fall, s.dt, s.t_end, runs));
  app.figure(kit::error_growth_figure(s.fall, s.dt, s.t_end, runs));
  app.figure(kit::orders_figure(s.fall, s.t_end, o));
  app.figure(kit::roundoff_figure(s.fall, s.t_end, r));
}
}  // namespace

int main(int argc, char** argv) {
  Setup s;
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR,
                      "Chapter 1: free fall, explicit and "
                      "implicit Euler");
  kit::add_free_fall_flags(app, s.fall, s.dt, s.t_end, s.dt_min);
  return app.run(argc, argv, [&] {
    the_system(app.report(), s);
    // Each section runs as soon as the exercises it needs are written (ex 1.1-1.3).
    const auto runs = app.section("loop and matrix", [&] { return loop_and_matrix_forms(app.report(), s); });
    const auto o = app.section("orders", [&] { return orders(app.report(), s); });
    const auto r = app.section("round-off", [&] { return roundoff(app.report(), s); });
    if (runs && o && r) figures(app, s, *runs, *o, *r);
  });
}
