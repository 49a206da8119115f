// Chapter 1: free fall with explicit and implicit Euler (lecture, "Chute libre").
// Both schemes miss the exact parabola by exactly k/2·Δt²·|g| after k steps (ERRATA item 1):
// explicit Euler above it, implicit Euler below it (y axis up, g < 0). The chapter checks that
// identity, measures local and global orders (ERRATA item 2), shrinks Δt until round-off wins,
// and prices each digit of accuracy.
#include <cmath>

#include <fmt/format.h>

#include <kit/chapter_app.hpp>
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
using kit::Trajectory;
using kit::Vec2;

// x_n − x̃(nΔt) after n explicit Euler steps of Δt = T/n on f(t, u) = (v, g), in precision S.
template <class S>
double explicit_error(const FreeFall& fall, double t_end, long n, long* rhs_evals = nullptr) {
  using State = kit::Vec<2, S>;
  const auto dt = S(t_end / double(n)), g = S(fall.g);
  auto f = [g](S, const State& u) { return State(u[1], g); };
  long evals = 0;
  kit::CountingRhs<decltype(f)> counted{f, evals};
  const auto u = kit::advance(fall.initial_state().cast<S>().eval(), n,
                              [&](const State& s) { return kit::explicit_euler_step(counted, S(0), s, dt); });
  if (rhs_evals) *rhs_evals = evals;
  return double(u[0]) - fall.position(double(n) * double(dt));
}

// The same for implicit Euler in matrix form.
template <class S>
double implicit_error(const FreeFall& fall, double t_end, long n) {
  const auto dt = S(t_end / double(n));
  const kit::ImplicitEulerAffine<2, S> implicit(fall.affine().cast<S>(), dt);
  const auto u = kit::advance(fall.initial_state().cast<S>().eval(), n, [&](const auto& s) { return implicit.step(s); });
  return double(u[0]) - fall.position(double(n) * double(dt));
}

// x_k − x̃(t_k) along a trajectory: positive = above the exact parabola.
std::vector<double> gap(const Trajectory<Vec2>& run, const FreeFall& fall) {
  std::vector<double> e;
  for (std::size_t k = 0; k < run.size(); ++k) e.push_back(run.u[k][0] - fall.position(run.t[k]));
  return e;
}

// A straight line y = slope·x through the origin, sampled at xs (the predictions).
std::vector<double> line(const std::vector<double>& xs, double slope, double power = 1) {
  std::vector<double> y;
  for (double x : xs) y.push_back(slope * std::pow(x, power));
  return y;
}
}  // namespace

int main(int argc, char** argv) {
  FreeFall fall;         // x0 = 20 m, v0 = 0 m/s, g = −9.81 m/s² (y axis up)
  double dt = 0.1;       // [s]
  double t_end = 1.0;    // [s]
  double dt_min = 1e-9;  // [s], the smallest step of the round-off sweep
  kit::ChapterApp app(KIT_CHAPTER_NAME, KIT_DEFAULT_FIGURE_DIR, "Chapter 1: free fall, explicit and implicit Euler");
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
      throw kit::UsageError(fmt::format("--t-end {} / --dt {} = {:.6g} steps: expected a whole number in [1, 1e6]",
                                        t_end, dt, t_end / dt));
    if (std::abs(fall.g) < 1e-3)
      throw kit::UsageError(fmt::format("--g {}: |g| must be at least 1e-3 m/s^2, or the errors this chapter measures vanish in round-off", fall.g));
    if (!(dt_min * 10 <= t_end) || t_end / dt_min > 2e9)
      throw kit::UsageError(fmt::format("--t-end {} / --dt-min {} = {:.3g} steps for the round-off sweep: expected between 10 and 2e9 "
                                        "(raise --dt-min or lower --t-end)", t_end, dt_min, t_end / dt_min));
    auto& out = app.text();
    auto& json = app.summary();
    const double g = std::abs(fall.g);
    const Vec2 u0 = fall.initial_state();

    // 2. The lecture's loop (explicit Euler on f), both matrix forms, and GSL's rk8pd.
    long evals = 0;
    kit::CountingRhs<FreeFall> f{fall, evals};
    const auto loop = kit::record(u0, dt, n, [&](const Vec2& u) { return kit::explicit_euler_step(f, 0.0, u, dt); });
    const auto euler_runs = [&](double h) {
      const kit::ExplicitEulerAffine<2> forward(fall.affine(), h);
      const kit::ImplicitEulerAffine<2> backward(fall.affine(), h);
      const long m = kit::whole_steps(t_end, h);
      return std::pair{kit::record(u0, h, m, [&](const Vec2& u) { return forward.step(u); }),
                       kit::record(u0, h, m, [&](const Vec2& u) { return backward.step(u); })};
    };
    const auto [expl, impl] = euler_runs(dt);
    kit::Stats reference_stats;
    const auto reference = kit::reference_solution(fall, 0.0, u0, loop.t, {}, &reference_stats);

    // 3. The error after k steps against the prediction k/2·Δt²·|g| (ERRATA item 1).
    out << fmt::format("Free fall: x0 = {} m, v0 = {} m/s, g = {} m/s^2 (y axis up), dt = {} s, {} steps\n"
                       "err = x_method - x_exact; positive = above the exact parabola\n\n", fall.x0, fall.v0, fall.g, dt, n);
    kit::Table table({"k", "t [s]", "exact x [m]", "explicit x", "implicit x", "explicit err", "implicit err",
                      "k/2·Δt²·|g|", "match"});
    const auto gap_expl = gap(expl, fall), gap_impl = gap(impl, fall);
    const double scale = std::abs(fall.x0) + std::abs(fall.v0) * t_end + g * t_end * t_end + 1.0;  // [m]
    double mismatch = 0, loop_vs_matrix = 0, reference_error = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const double exact = fall.position(loop.t[k]), predicted = fall.euler_error(long(k), dt);
      mismatch = std::max({mismatch, std::abs(std::abs(gap_expl[k]) - predicted), std::abs(std::abs(gap_impl[k]) - predicted)});
      loop_vs_matrix = std::max(loop_vs_matrix, std::abs(loop.u[k][0] - expl.u[k][0]));
      reference_error = std::max(reference_error, std::abs(reference.u[k][0] - exact));
      // Agreement to round-off (1e-9 relative + 1e-12 of the motion's scale), on the right side.
      const bool match = kit::agrees(std::abs(gap_expl[k]), predicted, 1e-9, 1e-12 * scale) &&
                         kit::agrees(std::abs(gap_impl[k]), predicted, 1e-9, 1e-12 * scale) &&
                         gap_expl[k] * fall.g <= 0 && gap_impl[k] * fall.g >= 0;
      if (k % std::max<std::size_t>(1, loop.size() / 10) != 0 && k + 1 != loop.size()) continue;
      table.add_row({std::to_string(k), kit::fixed(loop.t[k], 4), kit::fixed(exact, 6), kit::fixed(expl.u[k][0], 6),
                     kit::fixed(impl.u[k][0], 6), kit::sci(gap_expl[k], 5), kit::sci(gap_impl[k], 5),
                     kit::sci(predicted, 5), match ? "✓" : "✗"});
      json["samples"].push_back({{"k", k}, {"t", loop.t[k]}, {"exact", exact}, {"explicit", expl.u[k][0]},
                                 {"explicit_loop", loop.u[k][0]}, {"implicit", impl.u[k][0]},
                                 {"reference", reference.u[k][0]}, {"explicit_error", gap_expl[k]},
                                 {"implicit_error", gap_impl[k]}, {"predicted_error", predicted}, {"match", match}});
    }
    table.print(out);
    out << fmt::format("\nOver all {} steps, | |err| - k/2·Δt²·|g| | <= {:.3g} m; the loop and the matrix form differ by {:.3g} m.\n"
                       "GSL rk8pd reference: max |x - exact| = {:.3g} m, {} right-hand-side evaluations.\n",
                       n, mismatch, loop_vs_matrix, reference_error, reference_stats.rhs_evals);
    json.update({{"steps", n}, {"rhs_evals", evals}, {"max_prediction_mismatch", mismatch}, {"loop_vs_matrix", loop_vs_matrix},
                 {"reference", {{"max_error", reference_error}, {"rhs_evals", reference_stats.rhs_evals}}}});

    // 4. Orders (ERRATA item 2): the error after one step ∝ Δt², the error at a fixed time T ∝ Δt.
    kit::Sweep global_expl, global_impl, local_expl, local_impl;
    for (long m : kit::geometric_counts(10, 10'000, 4)) {
      const double h = t_end / double(m);
      global_expl.add(h, std::abs(explicit_error<double>(fall, t_end, m)));
      global_impl.add(h, std::abs(implicit_error<double>(fall, t_end, m)));
      local_expl.add(h, std::abs(explicit_error<double>(fall, h, 1)));
      local_impl.add(h, std::abs(implicit_error<double>(fall, h, 1)));
    }
    out << fmt::format("\nObserved orders, least-squares slopes over dt = {:.3g} .. {:.3g} s:\n"
                       "  error at T = {} s:     explicit {:.4f}, implicit {:.4f}  (global error, expected 1)\n"
                       "  error after one step: explicit {:.4f}, implicit {:.4f}  (local error, expected 2)\n",
                       global_expl.dt.front(), global_expl.dt.back(), t_end, global_expl.order(), global_impl.order(),
                       local_expl.order(), local_impl.order());
    json["convergence"] = {{"dt", global_expl.dt}, {"global_explicit", global_expl.error}, {"global_implicit", global_impl.error},
                           {"local_explicit", local_expl.error}, {"local_implicit", local_impl.error},
                           {"slopes", {{"global_explicit", global_expl.order()}, {"global_implicit", global_impl.order()},
                                       {"local_explicit", local_expl.order()}, {"local_implicit", local_impl.order()}}}};

    // 5. The extreme: shrink Δt until round-off wins, in double and in float, and price each digit.
    kit::Sweep doubles, roundoff_part, floats, floats_implicit;
    kit::Table cost({"Δt [s]", "steps", "RHS evals", "|error| [m]", "time [s]", "ns/step"});
    for (long m : kit::geometric_counts(std::max(1L, std::lround(t_end / 0.1)), std::lround(t_end / dt_min), 4)) {
      const double h = t_end / double(m);
      long m_evals = 0;
      double seconds = 0;
      const double error = std::abs(kit::time_per_call([&] { return explicit_error<double>(fall, t_end, m, &m_evals); }, seconds));
      doubles.add(h, error);
      roundoff_part.add(h, std::abs(error - 0.5 * t_end * h * g));  // what truncation does not explain
      json["cost"].push_back({{"dt", h}, {"steps", m}, {"rhs_evals", m_evals}, {"error", error}, {"seconds", seconds}});
      if (doubles.dt.size() % 4 == 1)
        cost.add_row({kit::sci(h, 2), std::to_string(m), std::to_string(m_evals), kit::sci(error, 3), kit::sci(seconds, 2),
                      kit::fixed(1e9 * seconds / double(m), 2)});
      if (h < 1e-7) continue;  // float has long stagnated there: x + Δt·v rounds back to x
      floats.add(h, std::abs(explicit_error<float>(fall, t_end, m)));
      floats_implicit.add(h, std::abs(implicit_error<float>(fall, t_end, m)));
    }
    out << "\nWhat accuracy costs (explicit Euler, double, T = " << t_end << " s): each digit costs 10x the steps\n";
    cost.print(out);
    out << "\nWhere round-off wins (the error falls with dt, then rises again):\n";
    kit::Sweep bests;
    for (auto [key, s] : {std::pair{"explicit_double", &doubles}, {"explicit_float", &floats}, {"implicit_float", &floats_implicit}}) {
      const std::size_t best = s->best();
      bests.add(s->dt[best], s->error[best]);
      out << fmt::format("  {:<16} best dt = {:.3g} s with |error| = {:.3g} m; at dt = {:.3g} s: {:.3g} m\n", key,
                         s->dt[best], s->error[best], s->dt.back(), s->error.back());
      json["roundoff"][key] = s->to_json();
      json["roundoff"][key].update({{"best_dt", s->dt[best]}, {"best_error", s->error[best]}});
    }
    json["roundoff"]["explicit_double"]["roundoff_part"] = roundoff_part.error;

    // 6. The figures, each with its sign convention.
    const std::string axes = fall.g < 0 ? "y axis up, g < 0" : "y axis up, g > 0";
    const std::string red = kit::look::explicit_euler, blue = kit::look::implicit_euler;
    kit::Figure trajectories("trajectories", fmt::format("Free fall with Δt = {} s ({})", dt, axes));
    trajectories.height_in = 5.5;
    trajectories.left_edge = 0.09, trajectories.right_edge = 0.74;
    auto& top = trajectories.panel("time t [s]", "height x [m]", "positions");
    top.place = {{0.0, 0.36, 1.0, 0.57}};
    top.key = "outside right";
    std::vector<double> fine_t, fine_x;  // the exact parabola, drawn smooth
    for (int i = 0; i <= 200; ++i) fine_t.push_back(t_end * i / 200.0), fine_x.push_back(fall.position(fine_t.back()));
    top.line("exact x0 + v0·t + g·t²/2", fine_t, fine_x, kit::look::exact);
    top.add({"explicit Euler", loop.t, expl.component(0), "linespoints", red + " pt 7 ps 0.8"});
    top.add({"implicit Euler", loop.t, impl.component(0), "linespoints", blue + " pt 6"});
    top.points("GSL rk8pd reference", loop.t, reference.component(0), kit::look::reference + " pt 2");
    auto& below = trajectories.panel("time t [s]", "x - x_{exact} [m]", "the gap (positive = above the exact parabola)");
    below.place = {{0.0, 0.0, 1.0, 0.36}};
    below.key = "outside right";
    below.add({"explicit Euler", loop.t, gap_expl, "linespoints", red + " pt 7 ps 0.8"});
    below.add({"implicit Euler", loop.t, gap_impl, "linespoints", blue + " pt 6"});
    app.figure(trajectories);

    kit::Figure growth("error-vs-time", fmt::format("Euler's error grows linearly in time, with slope Δt·|g|/2 ({})", axes));
    auto& lines = growth.panel("time t [s]", "x_k - x_{exact}(t_k) [m]   (positive = above)");
    lines.key = "outside right";
    for (auto [h, mark] : {std::pair{dt, 7}, {dt / 2, 9}, {dt / 4, 5}}) {
      const auto [e, i] = euler_runs(h);
      lines.points(fmt::format("explicit, Δt = {:g} s", h), e.t, gap(e, fall), red + fmt::format(" pt {} ps 0.9", mark));
      lines.points(fmt::format("implicit, Δt = {:g} s", h), i.t, gap(i, fall), blue + fmt::format(" pt {} ps 0.9", mark - 1));
      lines.line(h == dt ? "prediction ±t·Δt·|g|/2" : "", e.t, line(e.t, 0.5 * h * g), kit::look::prediction);
      lines.line("", e.t, line(e.t, -0.5 * h * g), kit::look::prediction);
    }
    app.figure(growth);

    kit::Figure orders("convergence", "Euler's order: error after one step ∝ Δt², error at a fixed time T ∝ Δt");
    auto& loglog = orders.panel("time step Δt [s]", "|x - x_{exact}| [m]");
    loglog.logx = loglog.logy = true;
    loglog.key = "bottom right";
    const auto slope = [](const char* what, const kit::Sweep& s) { return fmt::format("{}: slope {:.3f}", what, s.order()); };
    loglog.points(slope("explicit, at T", global_expl), global_expl.dt, global_expl.error, red + " pt 7 ps 0.8");
    loglog.points(slope("implicit, at T", global_impl), global_impl.dt, global_impl.error, blue + " pt 6 ps 1.6");
    loglog.points(slope("explicit, after one step", local_expl), local_expl.dt, local_expl.error, red + " pt 5 ps 0.8");
    loglog.points(slope("implicit, after one step", local_impl), local_impl.dt, local_impl.error, blue + " pt 4 ps 1.6");
    loglog.line("predictions T·Δt·|g|/2 and Δt²·|g|/2", global_expl.dt, line(global_expl.dt, 0.5 * t_end * g), kit::look::prediction);
    loglog.line("", global_expl.dt, line(global_expl.dt, 0.5 * g, 2), kit::look::prediction);
    app.figure(orders);

    kit::Figure extreme("roundoff", fmt::format("Shrinking Δt until round-off wins: explicit and implicit Euler at T = {} s", t_end));
    extreme.width_in = 8.0;
    auto& sweep = extreme.panel("time step Δt [s]", "|x_N - x_{exact}(T)| [m]");
    sweep.logx = sweep.logy = true;
    sweep.key = "outside right";
    sweep.add({"explicit, double", doubles.dt, doubles.error, "linespoints", red + " pt 7 ps 0.7"});
    sweep.add({"explicit, double: round-off part", roundoff_part.dt, roundoff_part.error, "linespoints", red + " dt 3 pt 1"});
    sweep.add({"explicit, float", floats.dt, floats.error, "linespoints", kit::look::single_precision + " lw 3 pt 5 ps 1.1"});
    sweep.add({"implicit, float", floats_implicit.dt, floats_implicit.error, "linespoints", blue + " dt 2 pt 6 ps 1.3"});
    sweep.line("truncation alone, T·Δt·|g|/2", doubles.dt, line(doubles.dt, 0.5 * t_end * g), kit::look::prediction);
    sweep.points("best Δt of each curve", bests.dt, bests.error, kit::look::highlight + " lw 2 pt 8 ps 2.5");
    app.figure(extreme);
  });
}
