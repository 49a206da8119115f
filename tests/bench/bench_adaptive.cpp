// ./kit bench adaptive: the DOPRI5 against Hairer's published counts and against GSL and
// Boost.Odeint run in this same process. Timings live here, never in the tests.
#include <algorithm>
#include <array>
#include <functional>
#include <limits>
#include <cstdio>
#include <vector>

#include <fmt/format.h>

#include <kit/dopri5.hpp>
#include <kit/measure.hpp>
#include <kit/peers.hpp>
#include <kit/stopwatch.hpp>
#include <kit/table.hpp>
#include <kit/adaptive_rk_models.hpp>

namespace {
// Seconds of the least disturbed call of each run. The runs take turns, round after round, in a
// rotating order, so that all of them meet the same disturbances from the rest of the machine;
// the minimum over the rounds is the cost of the code itself.
template <std::size_t K>
std::array<double, K> fastest_interleaved(const std::array<std::function<void()>, K>& runs, int rounds = 301) {
  std::array<double, K> best;
  best.fill(std::numeric_limits<double>::infinity());
  for (int round = 0; round < rounds; ++round)
    for (std::size_t turn = 0; turn < K; ++turn) {
      const std::size_t i = (turn + std::size_t(round)) % K;  // each run follows each other in turn
      const kit::Stopwatch clock;
      runs[i]();
      best[i] = std::min(best[i], clock.seconds());
    }
  return best;
}

struct Oscillator {  // y'' = −y: the cheapest right-hand side, so the integrator's own cost shows
  kit::Vec2 operator()(double, const kit::Vec2& y) const { return {y[1], -y[0]}; }
};
}  // namespace

int main() {
  const kit::Arenstorf arenstorf;
  const kit::Vec4 y0 = kit::Arenstorf::initial_state();
  const double period = kit::Arenstorf::period;

  fmt::print("1. Counts on Arenstorf against Hairer's dopri5.f (atol = rtol = tol, h0 = 1e-4)\n");
  kit::Table counts({"tol", "evals (kit)", "evals (Hairer)", "ratio", "steps", "rejected", "error (kit)", "error (Hairer)"});
  struct Published { double tol; long evals; double error; };
  for (const Published& p : {Published{1e-6, 985, 4.4e-2}, {1e-8, 2161, 7.8e-5}, {1e-10, 5047, 2.4e-6}}) {
    kit::Dopri5Options o;
    o.rtol = o.atol = p.tol, o.h0 = 1e-4;
    const auto r = kit::dopri5(arenstorf, 0.0, y0, period, o);
    counts.add_row({kit::sci(p.tol, 1), std::to_string(r.stats.rhs_evals), std::to_string(p.evals),
                    kit::fixed(double(r.stats.rhs_evals) / double(p.evals), 4), std::to_string(r.stats.steps + r.stats.rejected),
                    std::to_string(r.stats.rejected), kit::sci((r.y - y0).cwiseAbs().maxCoeff(), 2), kit::sci(p.error, 2)});
  }
  counts.print(std::cout);

  fmt::print("\n2. Evaluations needed to reach an error at T on Arenstorf (reference: GSL rk8pd at 1e-14); ratio < 1: the kit needs fewer\n");
  kit::GslOptions tight;
  tight.rtol = tight.atol = 1e-14;
  const kit::Vec4 reference = kit::reference_solution(arenstorf, 0.0, y0, {period}, tight).u.back();
  struct Curve { const char* name; std::vector<double> cost, error; };
  std::vector<Curve> curves{{"DOPRI5 (kit)", {}, {}}, {"GSL rkck", {}, {}}, {"GSL rkf45", {}, {}}, {"Boost dopri5", {}, {}}};
  for (int e = 3; e <= 13; ++e) {
    const double tol = std::pow(10.0, -e);
    kit::Dopri5Options o;
    o.rtol = o.atol = tol, o.h0 = 1e-4;
    const auto mine = kit::dopri5(arenstorf, 0.0, y0, period, o);
    curves[0].cost.push_back(double(mine.stats.rhs_evals)), curves[0].error.push_back((mine.y - reference).cwiseAbs().maxCoeff());
    for (auto [i, stepper] : {std::pair{1, kit::GslStepper::rkck}, {2, kit::GslStepper::rkf45}}) {
      const auto r = kit::gsl_peer(arenstorf, 0.0, y0, period, stepper, tol, 1e-4);
      curves[std::size_t(i)].cost.push_back(double(r.rhs_evals)), curves[std::size_t(i)].error.push_back((r.y - reference).cwiseAbs().maxCoeff());
    }
    const auto b = kit::boost_dopri5_peer(arenstorf, 0.0, y0, period, tol, 1e-4);
    curves[3].cost.push_back(double(b.rhs_evals)), curves[3].error.push_back((b.y - reference).cwiseAbs().maxCoeff());
  }
  kit::Table work({"error", "DOPRI5 (kit)", "GSL rkck", "ratio", "GSL rkf45", "ratio", "Boost dopri5", "ratio"});
  for (double target : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
    std::vector<std::string> row{kit::sci(target, 1)};
    const double mine = kit::cost_to_reach(curves[0].cost, curves[0].error, target);
    row.push_back(kit::fixed(mine, 0));
    for (std::size_t i = 1; i < curves.size(); ++i) {
      const double peer = kit::cost_to_reach(curves[i].cost, curves[i].error, target);
      row.push_back(std::isnan(peer) ? "not reached" : kit::fixed(peer, 0));
      row.push_back(std::isnan(peer) ? "-" : kit::fixed(mine / peer, 3));
    }
    work.add_row(row);
  }
  work.print(std::cout);

  fmt::print("\n3. Time per step on a 2-state oscillator (y'' = -y over 1000 time units, tol 1e-8): fastest of 301 interleaved runs\n");
  const Oscillator oscillator;
  const kit::Vec2 start(1.0, 0.0);
  kit::Dopri5Options o;
  o.rtol = o.atol = 1e-8, o.h0 = 1e-4;
  long kit_steps = 0, boost_evals = 0, gsl_evals = 0;
  double sink = 0;  // keeps every run's result alive
  const auto [kit_time, boost_time, gsl_time] = fastest_interleaved<3>({
      [&] {
        const auto r = kit::dopri5(oscillator, 0.0, start, 1000.0, o);
        kit_steps = r.stats.steps + r.stats.rejected, sink += r.y[0];
      },
      [&] {
        const auto r = kit::boost_dopri5_peer(oscillator, 0.0, start, 1000.0, 1e-8, 1e-4);
        boost_evals = r.rhs_evals, sink += r.y[0];
      },
      [&] {
        const auto r = kit::gsl_peer(oscillator, 0.0, start, 1000.0, kit::GslStepper::rkck, 1e-8, 1e-4);
        gsl_evals = r.rhs_evals, sink += r.y[0];
      }});
  // Steps from evaluations: dopri5 (FSAL) spends 6 per step, rkck 6 (5 stages + the derivative at the new point).
  const double boost_steps = double(boost_evals) / 6.0, gsl_steps = double(gsl_evals) / 6.0;
  kit::Table overhead({"integrator", "steps", "ns per step", "kit / this"});
  overhead.add_row({"DOPRI5 (kit)", std::to_string(kit_steps), kit::fixed(1e9 * kit_time / double(kit_steps), 1), "1.000"});
  overhead.add_row({"Boost.Odeint dopri5", kit::fixed(boost_steps, 0), kit::fixed(1e9 * boost_time / boost_steps, 1),
                    kit::fixed((kit_time / double(kit_steps)) / (boost_time / boost_steps), 3)});
  overhead.add_row({"GSL rkck", kit::fixed(gsl_steps, 0), kit::fixed(1e9 * gsl_time / gsl_steps, 1),
                    kit::fixed((kit_time / double(kit_steps)) / (gsl_time / gsl_steps), 3)});
  overhead.print(std::cout);
  return sink == 0 ? 1 : 0;
}
