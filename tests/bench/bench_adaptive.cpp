// ./kit bench adaptive: the DOPRI5 against Hairer's published counts and against GSL and
// Boost.Odeint run in this same process, every run measured by the work-precision harness of
// chapter 4 (kit/ode/work_precision.hpp). Timings live here, never in the tests.
#include <cmath>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include <kit/app/table.hpp>
#include <kit/ode/dopri5_work_method.hpp>
#include <kit/ode/reference_solver.hpp>
#include <kit/ode/work_precision.hpp>
#include <kit/ode/work_precision_methods.hpp>
#include <kit/problems/adaptive_rk_models.hpp>

namespace {
struct Oscillator {  // y'' = −y: the cheapest right-hand side, so the integrator's own cost shows
  kit::Vec2 operator()(double, const kit::Vec2& y) const { return {y[1], -y[0]}; }
};

std::string count(const std::optional<long>& n) { return n ? std::to_string(*n) : "-"; }
}  // namespace

int main() {
  const kit::Arenstorf arenstorf;
  const kit::Vec4 y0 = kit::Arenstorf::initial_state();
  const double period = kit::Arenstorf::period, h0 = 1e-4;
  const kit::WorkTiming counts_only{1, 0.0};  // sections 1 and 2 compare counts: one run each

  fmt::print("1. Counts on Arenstorf against Hairer's dopri5.f (atol = rtol = tol, h0 = 1e-4; steps = "
             "accepted + rejected)\n");
  struct Published {
    long evals;
    double error;
  };
  const std::vector<Published> hairer{{985, 4.4e-2}, {2161, 7.8e-5}, {5047, 2.4e-6}};
  const auto own = kit::measure_work_precision<4>(
      {kit::dopri5_method(arenstorf, 0.0, y0, period, h0, {1e-6, 1e-8, 1e-10})}, y0,
      counts_only)[0];  // the orbit closes: y(T) = y0 to 3e-8
  kit::Table counts({"tol", "evals (kit)", "evals (Hairer)", "ratio", "steps", "rejected", "error (kit)",
                     "error (Hairer)"});
  for (std::size_t i = 0; i < hairer.size(); ++i) {
    const kit::WorkPoint& p = own.points[i];
    counts.add_row({kit::sci(p.tolerance, 1), std::to_string(p.rhs_evals), std::to_string(hairer[i].evals),
                    kit::fixed(double(p.rhs_evals) / double(hairer[i].evals), 4), count(p.attempts()),
                    count(p.rejected), kit::sci(p.error, 2), kit::sci(hairer[i].error, 2)});
  }
  counts.print(std::cout);

  fmt::print("\n2. Evaluations needed to reach an error at T on Arenstorf (reference: GSL rk8pd at 1e-14); "
             "ratio < 1: the kit needs fewer\n");
  kit::GslOptions tight;
  tight.rtol = tight.atol = 1e-14;
  const kit::Vec4 reference = kit::reference_solution(arenstorf, 0.0, y0, {period}, tight).u.back();
  const std::vector<double> tolerances = kit::decades(3, 13);
  const auto curves = kit::measure_work_precision<4>(
      {kit::dopri5_method(arenstorf, 0.0, y0, period, h0, tolerances),
       kit::gsl_method(kit::GslStepper::rkck, arenstorf, 0.0, y0, period, h0, tolerances),
       kit::gsl_method(kit::GslStepper::rkf45, arenstorf, 0.0, y0, period, h0, tolerances),
       kit::boost_dopri5_method(arenstorf, 0.0, y0, period, h0, tolerances)},
      reference, counts_only);
  std::vector<std::string> headers{"error"};
  for (const auto& c : curves) {
    headers.push_back(c.label);
    if (&c != &curves[0]) headers.push_back("ratio");
  }
  kit::Table work(headers);
  for (double target : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
    std::vector<std::string> row{kit::sci(target, 1)};
    const double mine = curves[0].evaluations_to_reach(target);
    row.push_back(kit::fixed(mine, 0));
    for (std::size_t i = 1; i < curves.size(); ++i) {
      const double peer = curves[i].evaluations_to_reach(target);
      row.push_back(std::isnan(peer) ? "not reached" : kit::fixed(peer, 0));
      row.push_back(std::isnan(peer) ? "-" : kit::fixed(mine / peer, 3));
    }
    work.add_row(row);
  }
  work.print(std::cout);

  fmt::print("\n3. Time per step on a 2-state oscillator (y'' = -y over 1000 time units, tol 1e-8): fastest "
             "of 301 interleaved runs\n");
  const Oscillator oscillator;
  const kit::Vec2 start(1.0, 0.0), exact(std::cos(1000.0), -std::sin(1000.0));
  const auto timed = kit::measure_work_precision<2>(
      {kit::dopri5_method(oscillator, 0.0, start, 1000.0, h0, {1e-8}),
       kit::boost_dopri5_method(oscillator, 0.0, start, 1000.0, h0, {1e-8}),
       kit::gsl_method(kit::GslStepper::rkck, oscillator, 0.0, start, 1000.0, h0, {1e-8})},
      exact, {301, 0.0});
  // Steps attempted: the kit and GSL count them; Boost counts only the accepted ones, so its
  // attempts come from evaluations: dopri5 (FSAL) spends 6 per attempt.
  const auto steps = [](const kit::WorkPoint& p) {
    return p.attempts() ? double(*p.attempts()) : double(p.rhs_evals) / 6.0;
  };
  const double kit_per_step = timed[0].points[0].seconds / steps(timed[0].points[0]);
  kit::Table overhead({"integrator", "steps", "ns per step", "kit / this"});
  for (const auto& c : timed) {
    const kit::WorkPoint& p = c.points[0];
    overhead.add_row({c.label, kit::fixed(steps(p), 0), kit::fixed(1e9 * p.seconds / steps(p), 1),
                      kit::fixed(kit_per_step / (p.seconds / steps(p)), 3)});
  }
  overhead.print(std::cout);
  return 0;
}
