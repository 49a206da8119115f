// Chapter 4: adaptive Runge–Kutta (lecture, "Calcul automatique du pas de temps", and the
// tableau it labels "Dormand-Prince (ode45)"). The lecture's step doubling, guarded against the
// endless loop it can fall into (ERRATA item 10); embedded pairs, with Cash–Karp correctly named
// and its sign fixed (items 8–9); the production DOPRI5; and a work-precision diagram against
// GSL and Boost.Odeint run in the same process on the same problem.
#include <cmath>
#include <functional>
#include <map>

#include <fmt/format.h>

#include <kit/butcher_tableau.hpp>
#include <kit/chapter_app.hpp>
#include <kit/dopri5.hpp>
#include <kit/embedded_run.hpp>
#include <kit/peers.hpp>
#include <kit/stopwatch.hpp>
#include <kit/table.hpp>
#include <kit/adaptive_rk_models.hpp>

#include "embedded_rk.hpp"
#include "pi_controller.hpp"
#include "explicit_euler.hpp"
#include "midpoint.hpp"
#include "rk4.hpp"
#include "step_doubling.hpp"

namespace {
using kit::Vec4;

// The general driver runs the student's embedded step (ex 4.2) with the student's law (ex 4.3).
const auto embedded_step = [](const auto&... args) { return kit::embedded_step(args...); };

// One point of a work-precision curve: the error reached at T and what it cost.
struct Work {
  double tolerance = 0, error = 0, seconds = 0;
  long evaluations = 0, steps = 0, rejected = 0;
};
struct Curve {
  std::string label, look;
  std::vector<Work> points;
};

// A run of `solve(tolerance) → (y(T), evaluations, steps, rejected)`, timed over repetitions.
template <class Solve>
Work measure(double tolerance, const Vec4& reference, Solve&& solve) {
  Work w;
  w.tolerance = tolerance;
  const auto [y, evaluations, steps, rejected] = kit::time_per_call(solve, w.seconds);
  w.error = (y - reference).cwiseAbs().maxCoeff();
  w.evaluations = evaluations, w.steps = steps, w.rejected = rejected;
  return w;
}

using Outcome = std::tuple<Vec4, long, long, long>;
template <class Run>
Outcome outcome(const Run& run) {
  return {run.accepted.u.back(), run.stats.rhs_evals, run.stats.steps, run.stats.rejected};
}
}  // namespace

int main(int argc, char** argv) {
  double rtol = 1e-6, atol = 1e-6, h0 = 1e-4, e_min = 4e-7, e_max = 1e-6, mu = 100.0, eccentricity = 0.6;
  std::string problem = "arenstorf", method = "dopri5";
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 4: adaptive Runge-Kutta against GSL and Boost.Odeint");
  app.cli().add_option("--problem", problem, "arenstorf (orbit, T = 17.07) or kepler (eccentric orbit, T = 2π)")
      ->check(CLI::IsMember({"arenstorf", "kepler"}));
  app.cli().add_option("--method", method, "the detailed run: dopri5 (production), cash-karp or bogacki-shampine (general driver)")
      ->check(CLI::IsMember({"dopri5", "cash-karp", "bogacki-shampine"}));
  app.add_real("--rtol", rtol, "relative tolerance of the detailed run", kit::between(1e-13, 1e-1));
  app.add_real("--atol", atol, "absolute tolerance of the detailed run, units of y", kit::between(1e-13, 1e-1));
  app.add_real("--h0", h0, "first trial step [time units]", kit::between(1e-10, 1.0));
  app.add_real("--emin", e_min, "step doubling: double dt below this error", kit::between(1e-14, 1.0));
  app.add_real("--emax", e_max, "step doubling: halve dt above this error", kit::between(1e-14, 1.0));
  app.add_real("--eccentricity", eccentricity, "Kepler orbit eccentricity e", kit::between(0.0, 0.95));
  app.add_real("--mu", mu, "Van der Pol nonlinear damping μ (stiff when large)", kit::between(0.1, 1e4));

  return app.run(argc, argv, [&] {
    if (!(e_min < e_max)) throw kit::UsageError(fmt::format("--emin {} must be below --emax {}", e_min, e_max));
    auto& out = app.text();
    auto& json = app.summary();
    const kit::Kepler kepler{eccentricity};
    const bool orbit = problem == "arenstorf";
    const std::function<Vec4(double, const Vec4&)> f = orbit ? std::function<Vec4(double, const Vec4&)>(kit::Arenstorf{})
                                                              : std::function<Vec4(double, const Vec4&)>(kepler);
    const Vec4 y0 = orbit ? kit::Arenstorf::initial_state() : kepler.initial_state();
    const double t_end = orbit ? kit::Arenstorf::period : 2 * M_PI;
    // The reference: Kepler's exact solution, or GSL rk8pd at 1e-14 (Arenstorf closes only to 3e-8).
    kit::GslOptions tight;
    tight.rtol = tight.atol = 1e-14;
    const Vec4 reference = orbit ? kit::reference_solution(f, 0.0, y0, {t_end}, tight).u.back() : kepler.exact(t_end);

    // 1. The tableaus, checked: row sums and order conditions (ERRATA items 8–9).
    kit::Table tableaus({"tableau", "stages", "FSAL", "max |c - row sum|", "order of b", "order of b̂", "on autonomous problems"});
    for (const auto* t : {&kit::cash_karp(), &kit::cash_karp_as_printed(), &kit::dormand_prince(), &kit::bogacki_shampine()}) {
      const int p = kit::satisfied_order(*t, t->b), q = kit::satisfied_order(*t, t->b_hat);
      const int pa = kit::satisfied_order(*t, t->b, kit::Nodes::row_sums), qa = kit::satisfied_order(*t, t->b_hat, kit::Nodes::row_sums);
      tableaus.add_row({t->name, std::to_string(t->stages()), t->fsal ? "yes" : "no", kit::sci(double(kit::row_sum_defect(*t)), 2),
                        std::to_string(p), std::to_string(q), fmt::format("{} and {}", pa, qa)});
      json["tableaus"].push_back({{"name", t->name}, {"row_sum_defect", double(kit::row_sum_defect(*t))}, {"order", p},
                                  {"embedded_order", q}, {"order_autonomous", pa}, {"embedded_order_autonomous", qa}});
    }
    out << "Butcher tableaus, checked in long double (order conditions up to order 5):\n";
    tableaus.print(out);

    // 2. One run in detail: where it steps, what it rejects.
    kit::Dopri5Options options;
    options.rtol = rtol, options.atol = atol, options.h0 = h0;
    const auto& tableau = method == "cash-karp" ? kit::cash_karp() : kit::bogacki_shampine();
    const auto detail = method == "dopri5" ? kit::dopri5_run(f, 0.0, y0, t_end, options)
                                           : kit::embedded_run(embedded_step, kit::pi_step_factor, f, tableau, 0.0, y0, t_end, {rtol, atol, h0, 5'000'000});
    const std::string method_name = method == "dopri5" ? "DOPRI5" : tableau.name;
    const double detail_error = (detail.accepted.u.back() - reference).cwiseAbs().maxCoeff();
    out << fmt::format("\n{} on {} (rtol = {}, atol = {}, h0 = {}): {} evaluations, {} accepted and {} rejected steps, "
                       "max |y(T) - reference| = {:.3g}; {} {}\n", method_name, problem, rtol, atol, h0, detail.stats.rhs_evals,
                       detail.stats.steps, detail.stats.rejected, detail_error, kit::name(detail.status), detail.message);
    json["detail"] = {{"method", method_name}, {"rhs_evals", detail.stats.rhs_evals}, {"accepted", detail.stats.steps}, {"rejected", detail.stats.rejected},
                      {"error", detail_error}, {"status", kit::name(detail.status)}};

    // 3. Step doubling with explicit Euler (p = 1), as the lecture writes it and guarded.
    kit::StepDoubling doubling;
    doubling.e_min = e_min, doubling.e_max = e_max, doubling.dt0 = h0, doubling.max_steps = 2'000'000;
    long euler_evals = 0;
    const auto euler = [&](double t, const Vec4& y, double dt) { ++euler_evals; return kit::explicit_euler_step(f, t, y, dt); };
    out << fmt::format("\nStep doubling with explicit Euler, E_min = {}, E_max = {} (E_max/E_min = {:.3g}; halving dt divides e by ~2^(p+1) = 4):\n",
                       e_min, e_max, e_max / e_min);
    for (bool guarded : {false, true}) {
      doubling.guarded = guarded;
      euler_evals = 0;
      const auto run = kit::step_doubling(euler, 0.0, y0, t_end, doubling);
      const std::string what = run.status == kit::RunStatus::finished
                                   ? fmt::format("finished: {} accepted, {} rejected, {} evaluations, error {:.3g}", run.stats.steps,
                                                 run.stats.rejected, euler_evals, (run.accepted.u.back() - reference).cwiseAbs().maxCoeff())
                                   : fmt::format("{}: {}", kit::name(run.status), run.message);
      out << fmt::format("  {:<24} {}\n", guarded ? "guarded (accept e <= E_max):" : "the lecture's loop:", what);
      json["step_doubling"][guarded ? "guarded" : "lecture"] = {{"status", kit::name(run.status)}, {"message", run.message},
                                                                 {"accepted", run.stats.steps}, {"evaluations", euler_evals}};
    }

    // 4. Work against precision: every method on the same problem, in the same process.
    std::vector<Curve> curves;
    const auto add_curve = [&](std::string label, std::string look, const std::vector<double>& tolerances, auto&& solve) {
      Curve c{std::move(label), std::move(look), {}};
      for (double tol : tolerances) c.points.push_back(measure(tol, reference, [&] { return solve(tol); }));
      curves.push_back(std::move(c));
    };
    std::vector<double> tolerances;
    for (int e = 3; e <= 12; ++e) tolerances.push_back(std::pow(10.0, -e));
    add_curve("DOPRI5 (kit)", "lc rgb '#d62728' pt 7 lw 2", tolerances, [&](double tol) {
      kit::Dopri5Options o;
      o.rtol = o.atol = tol, o.h0 = h0;
      const auto r = kit::dopri5(f, 0.0, y0, t_end, o);
      return Outcome{r.y, r.stats.rhs_evals, r.stats.steps, r.stats.rejected};
    });
    for (const auto* tableau : {&kit::cash_karp(), &kit::bogacki_shampine()})
      add_curve(tableau->name + " (kit)", tableau == &kit::cash_karp() ? "lc rgb '#ff7f0e' pt 5" : "lc rgb '#bcbd22' pt 9",
                std::vector<double>(tolerances.begin(), tableau == &kit::cash_karp() ? tolerances.end() : tolerances.begin() + 6),
                [&](double tol) { return outcome(kit::embedded_run(embedded_step, kit::pi_step_factor, f, *tableau, 0.0, y0, t_end, {tol, tol, h0, 5'000'000})); });
    for (auto [stepper, look] : {std::pair{kit::GslStepper::rkck, "lc rgb '#1f77b4' pt 4 dt 2"}, {kit::GslStepper::rkf45, "lc rgb '#17becf' pt 6 dt 2"},
                                 {kit::GslStepper::rk8pd, "lc rgb '#9467bd' pt 8 dt 2"}})
      add_curve(fmt::format("GSL {}", kit::name(stepper)), look, tolerances, [&](double tol) {
        const auto r = kit::gsl_peer(f, 0.0, y0, t_end, stepper, tol, h0);
        return Outcome{r.y, r.rhs_evals, 0L, 0L};
      });
    add_curve("Boost.Odeint dopri5", "lc rgb '#2ca02c' pt 12 dt 2", tolerances, [&](double tol) {
      const auto r = kit::boost_dopri5_peer(f, 0.0, y0, t_end, tol, h0);
      return Outcome{r.y, r.rhs_evals, 0L, 0L};
    });
    add_curve("fixed-step RK4", "lc rgb '#8c564b' pt 13 dt 3", {3e3, 1e4, 3e4, 1e5, 3e5, 1e6}, [&](double n) {
      long evals = 0;
      const auto counted = [&](double t, const Vec4& y) { ++evals; return f(t, y); };
      Vec4 y = y0;
      const double dt = t_end / n;
      for (long k = 0; k < long(n); ++k) y = kit::rk4_step(counted, double(k) * dt, y, dt);
      return Outcome{y, evals, long(n), 0L};
    });
    for (auto [label, look, midpoint, count] : {std::tuple{"step doubling, Euler", "lc rgb '#e377c2' pt 2 dt 4", false, 5},
                                                {"step doubling, RK2", "lc rgb '#7f7f7f' pt 3 dt 4", true, 8}})
      add_curve(label, look, std::vector<double>(tolerances.begin(), tolerances.begin() + count), [&, midpoint = midpoint](double tol) {
        long evals = 0;
        const auto counted = [&](double t, const Vec4& y) { ++evals; return f(t, y); };
        kit::StepDoubling sd;
        sd.e_max = tol, sd.e_min = tol / 100, sd.dt0 = h0, sd.max_steps = 5'000'000;
        const auto step = [&](double t, const Vec4& y, double dt) {
          return midpoint ? kit::midpoint_step(counted, t, y, dt) : kit::explicit_euler_step(counted, t, y, dt);
        };
        const auto run = kit::step_doubling(step, 0.0, y0, t_end, sd);
        return Outcome{run.accepted.u.back(), evals, run.stats.steps, run.stats.rejected};
      });
    kit::Table work({"method", "tolerance", "RHS evals", "accepted", "rejected", "max |y(T) - ref|", "time [ms]"});
    for (const Curve& c : curves) {
      for (const Work& w : c.points) {
        work.add_row({c.label, kit::sci(w.tolerance, 1), std::to_string(w.evaluations), w.steps ? std::to_string(w.steps) : "-",
                      w.steps ? std::to_string(w.rejected) : "-", kit::sci(w.error, 3), kit::fixed(1e3 * w.seconds, 3)});
        json["work_precision"][c.label].push_back({{"tolerance", w.tolerance}, {"evaluations", w.evaluations}, {"accepted", w.steps},
                                                   {"rejected", w.rejected}, {"error", w.error}, {"seconds", w.seconds}});
      }
    }
    out << fmt::format("\nWork against precision on {} (tolerance = rtol = atol; fixed RK4: the number of steps):\n", problem);
    work.print(out);

    // 5. Stiffness: Van der Pol at large μ, where stability, not accuracy, holds the step down.
    const kit::VanDerPol vdp{mu};
    kit::Dopri5Options stiff;
    stiff.rtol = stiff.atol = 1e-6;
    stiff.max_steps = 2'000'000;
    const double t_vdp = 2 * (3 - 2 * std::log(2.0)) * mu;  // about two periods
    const auto vdp_run = kit::dopri5_run(vdp, 0.0, kit::VanDerPol::initial_state(), t_vdp, stiff);
    const auto median = [](std::vector<double> v) { std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end()); return v[v.size() / 2]; };
    // On the slow branches (|x| > 1.2) the Jacobian's stiff eigenvalue is about λ = −μ(x² − 1):
    // if stability holds the step down, h·|λ| sits at DOPRI5's real-axis boundary, 3.31.
    std::vector<double> h_lambda;
    for (std::size_t i = 0; i < vdp_run.step_sizes.size(); ++i) {
      const double x = vdp_run.accepted.u[i][0];
      if (std::abs(x) > 1.2) h_lambda.push_back(vdp_run.step_sizes[i] * mu * (x * x - 1));
    }
    const double median_h = median(vdp_run.step_sizes), median_h_lambda = median(h_lambda);
    const bool stability_bound = std::abs(median_h_lambda / 3.31 - 1) < 0.15;
    out << fmt::format("\nVan der Pol, mu = {}, over {:.4g} (two periods): DOPRI5 took {} steps and rejected {}; median step {:.3g}.\n"
                       "On the slow branches the median of h·|λ_stiff| = h·mu·(x² - 1) is {:.3g}, against DOPRI5's stability boundary\n"
                       "on the negative real axis, 3.31: {}. {}\n",
                       mu, t_vdp, vdp_run.stats.steps, vdp_run.stats.rejected, median_h, median_h_lambda,
                       stability_bound ? "stability, not accuracy, sets the step" : "below it, so accuracy still sets the step",
                       vdp_run.message);
    json["van_der_pol"] = {{"mu", mu}, {"accepted", vdp_run.stats.steps}, {"rejected", vdp_run.stats.rejected},
                           {"median_step", median_h}, {"median_h_lambda", median_h_lambda}, {"stability_bound", stability_bound}, {"status", kit::name(vdp_run.status)}};

    // 6. The figures.
    if (app.options().no_plot) return;
    kit::Figure path("orbit", fmt::format("{}: {}'s accepted steps (rtol = {}, atol = {})", orbit ? "Arenstorf orbit" : "Kepler orbit", method_name, rtol, atol));
    path.width_in = 6.5, path.height_in = 5.5;
    auto& xy = path.panel("x (Earth-Moon distances)", "y (Earth-Moon distances)");
    xy.commands = {"set size ratio -1"};
    xy.key = "outside right";
    const auto fine = kit::reference_solution(f, 0.0, y0, [&] { std::vector<double> t; for (int i = 1; i <= 2000; ++i) t.push_back(t_end * i / 2000); return t; }(), tight);
    xy.line("reference path (GSL rk8pd)", fine.component(0), fine.component(1), "lc rgb '#aaaaaa' lw 1");
    xy.points(fmt::format("accepted steps ({})", detail.stats.steps), detail.accepted.component(0), detail.accepted.component(1), "lc rgb '#d62728' pt 7 ps 0.5");
    if (orbit) xy.points("Earth, Moon", {-kit::Arenstorf::mu, 1 - kit::Arenstorf::mu}, {0.0, 0.0}, "lc rgb '#000000' pt 6 ps 2 lw 2");
    app.figure(path);

    kit::Figure steps("step-sizes", method_name + "'s step size along the run: small where the orbit bends sharply");
    auto& hs = steps.panel("t (time units)", "step h (time units)");
    hs.logy = true;
    hs.key = "outside right";
    std::vector<double> t_start(detail.accepted.t.begin(), detail.accepted.t.end() - 1);
    hs.add({"accepted", t_start, detail.step_sizes, "linespoints", "lc rgb '#d62728' pt 7 ps 0.4"});
    hs.points(fmt::format("rejected ({})", detail.rejected_t.size()), detail.rejected_t, detail.rejected_h, "lc rgb '#000000' pt 2 ps 1.2 lw 2");
    app.figure(steps);

    for (auto [name, title, by_time] : {std::tuple{"work-precision", "Error reached against right-hand-side evaluations", false},
                                        {"work-precision-time", "Error reached against wall time (this machine, this run)", true}}) {
      kit::Figure fig(name, fmt::format("{} ({})", title, problem));
      fig.width_in = 8;
      auto& p = fig.panel(by_time ? "wall time [s]" : "right-hand-side evaluations", "max |y(T) - reference|");
      p.logx = p.logy = true;
      p.key = "outside right";
      for (const Curve& c : curves) {
        std::vector<double> x, e;
        for (const Work& w : c.points) x.push_back(by_time ? w.seconds : double(w.evaluations)), e.push_back(std::max(w.error, 1e-16));
        p.add({c.label, x, e, "linespoints", c.look});
      }
      app.figure(fig);
    }

    kit::Figure stiffness("van-der-pol", fmt::format("Van der Pol, μ = {}: the explicit step is held down by stability", mu));
    stiffness.height_in = 5.5;
    auto& xs = stiffness.panel("t (time units)", "x");
    xs.place = {{0, 0.48, 1, 0.44}};
    xs.key = "outside right";
    xs.line("x(t)", vdp_run.accepted.t, vdp_run.accepted.component(0), "lc rgb '#000000'");
    auto& vh = stiffness.panel("t (time units)", "step h");
    vh.place = {{0, 0.0, 1, 0.46}};
    vh.logy = true;
    vh.key = "outside right";
    std::vector<double> v_start(vdp_run.accepted.t.begin(), vdp_run.accepted.t.end() - 1);
    vh.points(fmt::format("accepted ({})", vdp_run.stats.steps), v_start, vdp_run.step_sizes, "lc rgb '#d62728' pt 7 ps 0.3");
    vh.points(fmt::format("rejected ({})", vdp_run.stats.rejected), vdp_run.rejected_t, vdp_run.rejected_h, "lc rgb '#1f77b4' pt 2 ps 0.8");
    stiffness.left_edge = 0.08, stiffness.right_edge = 0.78;
    app.figure(stiffness);
  });
}
