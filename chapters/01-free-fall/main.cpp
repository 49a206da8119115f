// Chapter 1: free fall with explicit and implicit Euler (lecture, "Chute libre").
// Both schemes miss the exact parabola by exactly k/2·Δt²·|g| after k steps (ERRATA item 1):
// explicit Euler above it, implicit Euler below it (y axis up, g < 0). The chapter checks
// that identity, measures local and global orders (ERRATA item 2), shrinks Δt until
// round-off wins, and prices each digit of accuracy.
#include <cmath>

#include <fmt/format.h>

#include <kit/cli.hpp>
#include <kit/fixed_steps.hpp>
#include <kit/free_fall.hpp>
#include <kit/measure.hpp>
#include <kit/reference_solver.hpp>
#include <kit/stopwatch.hpp>
#include <kit/table.hpp>

#include "explicit_euler.hpp"
#include "implicit_euler.hpp"

namespace {
using kit::FreeFall;
using kit::Vec2;

// x_n − x̃(nΔt) after n steps of Δt = T/n, the state held in precision Scalar.
template <class Scalar>
double explicit_error(const FreeFall& fall, double t_end, long n, long* rhs_evals = nullptr) {
  using State = kit::Vec<2, Scalar>;
  const auto dt = static_cast<Scalar>(t_end / double(n)), g = static_cast<Scalar>(fall.g);
  auto f = [g](Scalar, const State& u) { return State(u[1], g); };  // f(t, u) = (v, g)
  long evals = 0;
  kit::CountingRhs<decltype(f)> counted{f, evals};
  const State u = kit::advance(fall.initial_state().cast<Scalar>().eval(), n,
                               [&](const State& s) { return kit::explicit_euler_step(counted, Scalar(0), s, dt); });
  if (rhs_evals) *rhs_evals = evals;
  return double(u[0]) - fall.position(double(n) * double(dt));
}

template <class Scalar>
double implicit_error(const FreeFall& fall, double t_end, long n) {
  const auto dt = static_cast<Scalar>(t_end / double(n));
  const kit::ImplicitEulerAffine<2, Scalar> implicit(fall.affine().cast<Scalar>(), dt);
  const auto u = kit::advance(fall.initial_state().cast<Scalar>().eval(), n, [&](const auto& s) { return implicit.step(s); });
  return double(u[0]) - fall.position(double(n) * double(dt));
}

struct Sweep {
  std::vector<double> dt, error;
};
}  // namespace

int main(int argc, char** argv) {
  FreeFall fall;         // x0 = 20 m, v0 = 0 m/s, g = −9.81 m/s² (y axis up)
  double dt = 0.1;       // [s]
  double t_end = 1.0;    // [s]
  double dt_min = 1e-9;  // [s], smallest step of the round-off sweep
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR,
                      "Chapter 1: free fall, explicit and implicit Euler against the exact parabola");
  app.add_real("--x0", fall.x0, "initial height x(0) [m], y axis up", kit::between(-1e6, 1e6));
  app.add_real("--v0", fall.v0, "initial velocity v(0) [m/s], positive upward", kit::between(-1e4, 1e4));
  auto gravity = kit::between(-1e3, 1e3);
  gravity.nonzero = true;
  app.add_real("--g", fall.g, "gravitational acceleration g [m/s^2], negative = downward", gravity);
  app.add_real("--dt", dt, "time step [s]", kit::positive(10.0));
  app.add_real("--t-end", t_end, "final time T [s], a whole number of steps", kit::positive(1e4));
  app.add_real("--dt-min", dt_min, "smallest time step of the round-off sweep [s]", kit::between(1e-12, 1e-3));

  return app.run(argc, argv, [&] {
    // 1. The system u = (x, v): x' = v, v' = g, over n whole steps of Δt.
    const long n = kit::whole_steps(t_end, dt);
    if (n == 0 || n > 1'000'000)
      throw kit::UsageError(fmt::format("--t-end {} / --dt {} = {:.6g} steps: expected a whole number in [1, 1e6]", t_end, dt, t_end / dt));
    auto& out = app.text();
    auto& json = app.summary();
    const Vec2 u0 = fall.initial_state();

    // 2. The lecture's loop (explicit Euler on f), both matrix forms, and GSL's rk8pd.
    long evals = 0;
    kit::CountingRhs<FreeFall> f{fall, evals};
    const auto loop = kit::record(u0, dt, n, [&](const Vec2& u) { return kit::explicit_euler_step(f, 0.0, u, dt); });
    const auto euler_pair = [&](double h) {
      const kit::ExplicitEulerAffine<2> expl(fall.affine(), h);
      const kit::ImplicitEulerAffine<2> impl(fall.affine(), h);
      const long m = kit::whole_steps(t_end, h);
      return std::pair{kit::record(u0, h, m, [&](const Vec2& u) { return expl.step(u); }),
                       kit::record(u0, h, m, [&](const Vec2& u) { return impl.step(u); })};
    };
    const auto [expl, impl] = euler_pair(dt);
    kit::Stats reference_stats;
    const auto reference = kit::reference_solution(fall, 0.0, u0, loop.t, {}, &reference_stats);

    // 3. The error after k steps against the prediction k/2·Δt²·|g| (ERRATA item 1).
    out << fmt::format("Free fall: x0 = {} m, v0 = {} m/s, g = {} m/s^2 (y axis up), dt = {} s, {} steps\n"
                       "err = x_method - x_exact; positive = above the exact parabola\n\n", fall.x0, fall.v0, fall.g, dt, n);
    kit::Table table({"k", "t [s]", "exact x [m]", "explicit x", "implicit x", "explicit err", "implicit err", "k/2·Δt²·|g|", "match"});
    const double scale = std::abs(fall.x0) + std::abs(fall.v0) * t_end + std::abs(fall.g) * t_end * t_end + 1.0;
    double loop_vs_matrix = 0, reference_error = 0, worst_mismatch = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const double exact = fall.position(loop.t[k]), predicted = fall.euler_error(long(k), dt);
      const double e_expl = expl.u[k][0] - exact, e_impl = impl.u[k][0] - exact;
      loop_vs_matrix = std::max(loop_vs_matrix, std::abs(loop.u[k][0] - expl.u[k][0]));
      reference_error = std::max(reference_error, std::abs(reference[k][0] - exact));
      worst_mismatch = std::max({worst_mismatch, std::abs(std::abs(e_expl) - predicted), std::abs(std::abs(e_impl) - predicted)});
      // Agreement to round-off: 1e-9 relative, plus 1e-12 of the motion's scale.
      const bool match = kit::agrees(std::abs(e_expl), predicted, 1e-9, 1e-12 * scale) &&
                         kit::agrees(std::abs(e_impl), predicted, 1e-9, 1e-12 * scale) && e_expl * fall.g <= 0 && e_impl * fall.g >= 0;
      if (k % std::max<std::size_t>(1, loop.size() / 10) != 0 && k + 1 != loop.size()) continue;
      table.add_row({std::to_string(k), kit::fixed(loop.t[k], 4), kit::fixed(exact, 6), kit::fixed(expl.u[k][0], 6), kit::fixed(impl.u[k][0], 6),
                     kit::sci(e_expl, 4), kit::sci(e_impl, 4), kit::sci(predicted, 4), match ? "✓" : "✗"});
      json["samples"].push_back({{"k", k}, {"t", loop.t[k]}, {"exact", exact}, {"explicit", expl.u[k][0]}, {"explicit_loop", loop.u[k][0]},
                                 {"implicit", impl.u[k][0]}, {"reference", reference[k][0]}, {"explicit_error", e_expl},
                                 {"implicit_error", e_impl}, {"predicted_error", predicted}, {"match", match}});
    }
    table.print(out);
    out << fmt::format("\nEvery step k: | |err| - k/2·Δt²·|g| | <= {:.3g} m. Lecture's loop against matrix form: {:.3g} m apart.\n"
                       "GSL rk8pd reference: max |x - exact| = {:.3g} m, {} right-hand-side evaluations.\n",
                       worst_mismatch, loop_vs_matrix, reference_error, reference_stats.rhs_evals);
    json.update({{"steps", n}, {"rhs_evals", evals}, {"max_prediction_mismatch", worst_mismatch}, {"loop_vs_matrix", loop_vs_matrix},
                 {"reference", {{"max_error", reference_error}, {"rhs_evals", reference_stats.rhs_evals}}}});

    // 4. Orders (ERRATA item 2): error after one step ∝ Δt², error at the fixed time T ∝ Δt.
    Sweep global_expl, global_impl, local_expl, local_impl;
    for (long m : kit::geometric_counts(10, 10'000, 4)) {
      const double h = t_end / double(m);
      for (Sweep* s : {&global_expl, &global_impl, &local_expl, &local_impl}) s->dt.push_back(h);
      global_expl.error.push_back(std::abs(explicit_error<double>(fall, t_end, m)));
      global_impl.error.push_back(std::abs(implicit_error<double>(fall, t_end, m)));
      local_expl.error.push_back(std::abs(explicit_error<double>(fall, h, 1)));
      local_impl.error.push_back(std::abs(implicit_error<double>(fall, h, 1)));
    }
    const auto slope = [](const Sweep& s) { return kit::fit_loglog(s.dt, s.error).slope; };
    const double slopes[4] = {slope(global_expl), slope(global_impl), slope(local_expl), slope(local_impl)};
    out << fmt::format("\nObserved orders, least-squares slopes over dt = {:.3g} .. {:.3g} s:\n"
                       "  error at T = {} s:     explicit {:.4f}, implicit {:.4f}  (global error, expected 1)\n"
                       "  error after one step: explicit {:.4f}, implicit {:.4f}  (local error, expected 2)\n",
                       global_expl.dt.front(), global_expl.dt.back(), t_end, slopes[0], slopes[1], slopes[2], slopes[3]);
    json["convergence"] = {{"dt", global_expl.dt}, {"global_explicit", global_expl.error}, {"global_implicit", global_impl.error},
                           {"local_explicit", local_expl.error}, {"local_implicit", local_impl.error},
                           {"slopes", {{"global_explicit", slopes[0]}, {"global_implicit", slopes[1]},
                                       {"local_explicit", slopes[2]}, {"local_implicit", slopes[3]}}}};

    // 5. The extreme: shrink Δt until round-off wins, in double and in float; price each digit.
    Sweep doubles, roundoff_part, floats, floats_implicit;
    kit::Table cost({"Δt [s]", "steps", "RHS evals", "|error| [m]", "time [s]", "ns/step"});
    for (long m : kit::geometric_counts(std::max(1L, std::lround(t_end / 0.1)), std::lround(t_end / dt_min), 4)) {
      const double h = t_end / double(m);
      long m_evals = 0;
      double seconds = 0;
      const double error = std::abs(kit::time_per_call([&] { return explicit_error<double>(fall, t_end, m, &m_evals); }, seconds));
      doubles.dt.push_back(h), doubles.error.push_back(error);
      roundoff_part.dt.push_back(h), roundoff_part.error.push_back(std::abs(error - 0.5 * t_end * h * std::abs(fall.g)));
      json["cost"].push_back({{"dt", h}, {"steps", m}, {"rhs_evals", m_evals}, {"error", error}, {"seconds", seconds}});
      if (doubles.dt.size() % 4 == 1)
        cost.add_row({kit::sci(h, 2), std::to_string(m), std::to_string(m_evals), kit::sci(error, 3), kit::sci(seconds, 2), kit::fixed(1e9 * seconds / double(m), 2)});
      if (h < 1e-7) continue;  // float stagnated long before: x + Δt·v rounds back to x
      floats.dt.push_back(h), floats.error.push_back(std::abs(explicit_error<float>(fall, t_end, m)));
      floats_implicit.dt.push_back(h), floats_implicit.error.push_back(std::abs(implicit_error<float>(fall, t_end, m)));
    }
    out << "\nWhat accuracy costs (explicit Euler, double, T = " << t_end << " s): each digit costs 10x the steps\n";
    cost.print(out);
    out << "\nWhere round-off wins (the error falls with dt, then rises again):\n";
    std::vector<double> best_dt, best_error;
    for (auto [key, s] : {std::pair{"explicit_double", &doubles}, {"explicit_float", &floats}, {"implicit_float", &floats_implicit}}) {
      const std::size_t best = kit::argmin(s->error);
      best_dt.push_back(s->dt[best]), best_error.push_back(s->error[best]);
      out << fmt::format("  {:<16} best dt = {:.3g} s with |error| = {:.3g} m; at dt = {:.3g} s: {:.3g} m\n", key, s->dt[best],
                         s->error[best], s->dt.back(), s->error.back());
      json["roundoff"][key] = {{"dt", s->dt}, {"error", s->error}, {"best_dt", s->dt[best]}, {"best_error", s->error[best]}};
    }
    json["roundoff"]["explicit_double"]["roundoff_part"] = roundoff_part.error;

    // 6. The figures, each with its sign convention.
    const std::string axis_note = fall.g < 0 ? "y axis up, g < 0" : "y axis up, g > 0";
    kit::Figure trajectories("trajectories", fmt::format("Free fall with Δt = {} s ({})", dt, axis_note));
    trajectories.height_in = 5.5;
    trajectories.left_edge = 0.09, trajectories.right_edge = 0.74;
    auto& top = trajectories.panel("time t [s]", "height x [m]", "positions");
    top.place = {{0.0, 0.36, 1.0, 0.57}};
    std::vector<double> fine_t, fine_x, gap_expl, gap_impl;
    for (int i = 0; i <= 200; ++i) fine_t.push_back(t_end * i / 200.0), fine_x.push_back(fall.position(fine_t.back()));
    for (std::size_t k = 0; k < loop.size(); ++k)
      gap_expl.push_back(expl.u[k][0] - fall.position(loop.t[k])), gap_impl.push_back(impl.u[k][0] - fall.position(loop.t[k]));
    top.line("exact x0 + v0·t + g·t²/2", fine_t, fine_x, kit::look::exact);
    top.add({"explicit Euler", loop.t, expl.component(0), "linespoints", kit::look::explicit_euler + " pt 7 ps 0.8"});
    top.add({"implicit Euler", loop.t, impl.component(0), "linespoints", kit::look::implicit_euler + " pt 6 ps 1.0"});
    top.points("GSL rk8pd reference", loop.t, [&] { std::vector<double> x; for (auto& r : reference) x.push_back(r[0]); return x; }(), kit::look::reference + " pt 2");
    top.key = "outside right";
    auto& gap = trajectories.panel("time t [s]", "x - x_{exact} [m]", "the gap (positive = above the exact parabola)");
    gap.place = {{0.0, 0.0, 1.0, 0.36}};
    gap.add({"explicit Euler", loop.t, gap_expl, "linespoints", kit::look::explicit_euler + " pt 7 ps 0.8"});
    gap.add({"implicit Euler", loop.t, gap_impl, "linespoints", kit::look::implicit_euler + " pt 6 ps 1.0"});
    gap.key = "outside right";
    app.figure(trajectories);

    kit::Figure growth("error-vs-time", fmt::format("Euler's error grows linearly in time, with slope Δt·|g|/2 ({})", axis_note));
    auto& lines = growth.panel("time t [s]", "x_k - x_{exact}(t_k) [m]   (positive = above)");
    for (auto [h, mark] : {std::pair{dt, 7}, {dt / 2, 9}, {dt / 4, 5}}) {
      const auto [e, i] = euler_pair(h);
      std::vector<double> ee, ei, up, down;
      for (std::size_t k = 0; k < e.size(); ++k) {
        ee.push_back(e.u[k][0] - fall.position(e.t[k])), ei.push_back(i.u[k][0] - fall.position(i.t[k]));
        up.push_back(0.5 * e.t[k] * h * std::abs(fall.g)), down.push_back(-up.back());
      }
      lines.points(fmt::format("explicit, Δt = {:g} s", h), e.t, ee, kit::look::explicit_euler + fmt::format(" pt {} ps 0.9", mark));
      lines.points(fmt::format("implicit, Δt = {:g} s", h), i.t, ei, kit::look::implicit_euler + fmt::format(" pt {} ps 0.9", mark - 1));
      lines.line(h == dt ? "prediction ±t·Δt·|g|/2" : "", e.t, up, kit::look::prediction);
      lines.line("", e.t, down, kit::look::prediction);
    }
    lines.key = "outside right";
    app.figure(growth);

    kit::Figure orders("convergence", "Euler's order: error after one step ∝ Δt², error at a fixed time T ∝ Δt");
    auto& loglog = orders.panel("time step Δt [s]", "|x - x_{exact}| [m]");
    loglog.logx = loglog.logy = true;
    loglog.points(fmt::format("explicit, at T = {} s: slope {:.3f}", t_end, slopes[0]), global_expl.dt, global_expl.error, kit::look::explicit_euler + " pt 7 ps 0.8");
    loglog.points(fmt::format("implicit, at T = {} s: slope {:.3f}", t_end, slopes[1]), global_impl.dt, global_impl.error, kit::look::implicit_euler + " pt 6 ps 1.6");
    loglog.points(fmt::format("explicit, after one step: slope {:.3f}", slopes[2]), local_expl.dt, local_expl.error, kit::look::explicit_euler + " pt 5 ps 0.8");
    loglog.points(fmt::format("implicit, after one step: slope {:.3f}", slopes[3]), local_impl.dt, local_impl.error, kit::look::implicit_euler + " pt 4 ps 1.6");
    std::vector<double> global_line, local_line;
    for (double h : global_expl.dt) global_line.push_back(0.5 * t_end * h * std::abs(fall.g)), local_line.push_back(0.5 * h * h * std::abs(fall.g));
    loglog.line("predictions T·Δt·|g|/2 and Δt²·|g|/2", global_expl.dt, global_line, kit::look::prediction);
    loglog.line("", global_expl.dt, local_line, kit::look::prediction);
    loglog.key = "bottom right";
    app.figure(orders);

    kit::Figure extreme("roundoff", fmt::format("Shrinking Δt until round-off wins: explicit and implicit Euler at T = {} s", t_end));
    auto& sweep = extreme.panel("time step Δt [s]", "|x_N - x_{exact}(T)| [m]");
    sweep.logx = sweep.logy = true;
    std::vector<double> truncation;
    for (double h : doubles.dt) truncation.push_back(0.5 * t_end * h * std::abs(fall.g));
    sweep.add({"explicit, double", doubles.dt, doubles.error, "linespoints", kit::look::explicit_euler + " pt 7 ps 0.7"});
    sweep.add({"explicit, double: round-off part", roundoff_part.dt, roundoff_part.error, "linespoints", kit::look::explicit_euler + " dt 3 pt 1"});
    sweep.add({"explicit, float", floats.dt, floats.error, "linespoints", kit::look::single_precision + " lw 3 pt 5 ps 1.1"});
    sweep.add({"implicit, float", floats_implicit.dt, floats_implicit.error, "linespoints", kit::look::implicit_euler + " dt 2 pt 6 ps 1.3"});
    sweep.line("truncation alone, T·Δt·|g|/2", doubles.dt, truncation, kit::look::prediction);
    sweep.points("best Δt of each curve", best_dt, best_error, kit::look::highlight + " lw 2 pt 8 ps 2.5");
    sweep.key = "outside right";
    extreme.width_in = 8.0;
    app.figure(extreme);
  });
}
