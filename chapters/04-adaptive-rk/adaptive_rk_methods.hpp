#pragma once
// Chapter 4's methods that run the student's code: the general embedded driver with ex 4.2's
// step and ex 4.3's law, the lecture's step doubling (ex 4.1) over explicit Euler or midpoint
// RK2 (ex 3.1), and fixed-step RK4 (ex 3.2), as runs and as WorkMethod for the work-precision
// harness (kit/ode/work_precision.hpp). Not an exercise: it only wires the student's files to the
// kit; the kit's own DOPRI5 and the peers are in kit/ode/work_precision_methods.hpp.
#include <string>
#include <utility>
#include <vector>

#include <kit/app/look.hpp>
#include <kit/app/progress.hpp>
#include <kit/app/report.hpp>
#include <kit/base/enum_names.hpp>
#include <kit/ode/adaptive_run.hpp>
#include <kit/ode/butcher_tableau.hpp>
#include <kit/ode/embedded_run.hpp>
#include <kit/ode/work_precision.hpp>
#include <kit/ode/work_precision_methods.hpp>

// The kit's production DOPRI5, unless this is a student edition without production code: then
// chapter 4's DOPRI5 is the student's own (ex 4.2 on the Dormand–Prince tableau, ex 4.3's PI law).
#if __has_include(<kit/ode/dopri5.hpp>)
#include <kit/ode/dopri5.hpp>
#include <kit/ode/dopri5_work_method.hpp>
#define KIT_PRODUCTION_DOPRI5 1
#else
#define KIT_PRODUCTION_DOPRI5 0
#endif

#include "embedded_rk.hpp"
#include "explicit_euler.hpp"
#include "midpoint.hpp"
#include "pi_controller.hpp"
#include "rk4.hpp"
#include "step_doubling.hpp"
#include "van_der_pol_stiffness.hpp"

namespace kit {

/// The general driver running the student's embedded step (ex 4.2) with the student's PI law (ex 4.3).
template <int N, class Rhs>
AdaptiveRun<Vec<N>> student_embedded_run(const Rhs& f, const ButcherTableau& tableau, double t0,
                                         const Vec<N>& y0, double t1, const EmbeddedOptions& options) {
  const auto step = [](const auto&... args) { return embedded_step(args...); };
  return embedded_run(step, pi_step_factor, f, tableau, t0, y0, t1, options);
}

/// One method's run, named and styled for the text and the figures.
template <int N>
struct NamedRun {
  std::string name;  ///< "DOPRI5", "Cash-Karp 5(4)", "Bogacki-Shampine 3(2)"
  std::string look;  ///< its colour (look.hpp)
  AdaptiveRun<Vec<N>> run;
};

/// The methods --method runs in detail: the kit's production DOPRI5, or one of the student's
/// pairs in the general driver. The display names are the tableaus' own (butcher_tableau.cpp).
enum class DetailedMethod { dopri5, cash_karp, bogacki_shampine };
inline constexpr auto detailed_method_names = enum_names<DetailedMethod>({
    {DetailedMethod::dopri5, "dopri5", "DOPRI5"},
    {DetailedMethod::cash_karp, "cash-karp", "Cash-Karp 5(4)"},
    {DetailedMethod::bogacki_shampine, "bogacki-shampine", "Bogacki-Shampine 3(2)"},
});
static_assert(detailed_method_names.in_order());

/// One run in detail of `method`.
template <int N, class Rhs>
NamedRun<N> detailed_run(DetailedMethod method, const Rhs& f, double t0, const Vec<N>& y0, double t1,
                         const EmbeddedOptions& options) {
  if (method == DetailedMethod::dopri5) {
#if KIT_PRODUCTION_DOPRI5
    Dopri5Options o;
    o.rtol = options.rtol, o.atol = options.atol, o.h0 = options.h0, o.max_steps = options.max_steps;
    return {"DOPRI5", look::dopri5, dopri5_run(f, t0, y0, t1, o)};
#else
    return {"DOPRI5 (ex 4.2, 4.3)", look::dopri5,
            student_embedded_run(f, dormand_prince(), t0, y0, t1, options)};
#endif
  }
  const bool ck = method == DetailedMethod::cash_karp;
  const ButcherTableau& tableau = ck ? cash_karp() : bogacki_shampine();
  return {tableau.name, ck ? look::cash_karp : look::bogacki_shampine,
          student_embedded_run(f, tableau, t0, y0, t1, options)};
}

/// The one-step method under the lecture's step doubling.
enum class DoublingBase { euler, midpoint };

/// The lecture's step doubling (ex 4.1) over `base`, with run.stats.rhs_evals counting every
/// evaluation of f (three steps of the base method per trial, ERRATA item 11).
template <int N, class Rhs>
AdaptiveRun<Vec<N>> counted_step_doubling(DoublingBase base, const Rhs& f, double t0, const Vec<N>& y0,
                                          double t1, const StepDoubling& options) {
  long evaluations = 0;
  const CountingRhs<Rhs> counted{f, evaluations};
  ProgressCounter progress;  // the trials, on the progress line
  const auto step = [&](double t, const Vec<N>& y, double dt) {
    progress.add(1);
    return base == DoublingBase::midpoint ? midpoint_step(counted, t, y, dt)
                                          : explicit_euler_step(counted, t, y, dt);
  };
  AdaptiveRun<Vec<N>> run = step_doubling(step, t0, y0, t1, options);
  run.stats.rhs_evals = evaluations;
  return run;
}

/// The counts of an adaptive run, as the harness wants them.
template <int N>
WorkRun<N> work_run(const AdaptiveRun<Vec<N>>& run) {
  return {run.accepted.u.back(), run.stats.rhs_evals, run.stats.steps, run.stats.rejected,
          run.status == RunStatus::finished};
}

/// The student's embedded pair in the general driver, at rtol = atol = tol from h0 (at most
/// 5·10⁶ steps).
template <int N, class Rhs>
WorkMethod<N> embedded_pair_method(const ButcherTableau& tableau, std::string look, Rhs f, double t0,
                                   const Vec<N>& y0, double t1, double h0, std::vector<double> tolerances) {
  return {tableau.name + " (kit)", std::move(look), std::move(tolerances),
          [&tableau, f, t0, y0, t1, h0](double tol) {
            return work_run(student_embedded_run(f, tableau, t0, y0, t1, {tol, tol, h0, 5'000'000}));
          }};
}

/// Chapter 4's DOPRI5 in the work-precision diagram: the production one (dopri5_work_method.hpp),
/// or the student's pair on the Dormand–Prince tableau in an edition without production code.
template <int N, class Rhs>
WorkMethod<N> chapter_dopri5_method(Rhs f, double t0, const Vec<N>& y0, double t1, double h0,
                                    std::vector<double> tolerances) {
#if KIT_PRODUCTION_DOPRI5
  return dopri5_method(f, t0, y0, t1, h0, std::move(tolerances));
#else
  return embedded_pair_method(dormand_prince(), look::dopri5 + " pt 7 lw 2", f, t0, y0, t1, h0,
                              std::move(tolerances));
#endif
}

/// Chapter 4's DOPRI5 for the stiffness run (van_der_pol_stiffness.hpp): the production one from
/// HINIT's first step, or the student's from h0 = 1e-4.
inline Dopri5Runner chapter_dopri5() {
  return [](const VanDerPol& f, const Vec2& y0, double t_end, long max_steps) {
#if KIT_PRODUCTION_DOPRI5
    Dopri5Options o;
    o.rtol = o.atol = 1e-6, o.max_steps = max_steps;
    return dopri5_run(f, 0.0, y0, t_end, o);
#else
    return student_embedded_run(f, dormand_prince(), 0.0, y0, t_end, {1e-6, 1e-6, 1e-4, max_steps});
#endif
  };
}

/// The lecture's step doubling over `base` with E_max = tol and E_min = tol/100 (a ratio that
/// cannot trap it), from dt0 = h0, at most 5·10⁶ steps.
template <int N, class Rhs>
WorkMethod<N> step_doubling_method(DoublingBase base, Rhs f, double t0, const Vec<N>& y0, double t1,
                                   double h0, std::vector<double> tolerances) {
  const bool euler = base == DoublingBase::euler;
  return {euler ? "step doubling, Euler" : "step doubling, RK2",
          (euler ? look::step_doubling_euler + " pt 2" : look::step_doubling_rk2 + " pt 3"),
          std::move(tolerances), [=](double tol) {
            StepDoubling options;
            options.e_max = tol, options.e_min = tol / 100, options.dt0 = h0, options.max_steps = 5'000'000;
            return work_run(counted_step_doubling(base, f, t0, y0, t1, options));
          }};
}

/// Fixed-step RK4 (ex 3.2): its "tolerances" are step counts n, Δt = (t1 − t0)/n.
template <int N, class Rhs>
WorkMethod<N> fixed_rk4_method(Rhs f, double t0, const Vec<N>& y0, double t1,
                               std::vector<double> step_counts) {
  return {"fixed-step RK4", look::fixed_rk4 + " pt 13", std::move(step_counts), [=](double count) {
            long evaluations = 0;
            const CountingRhs<Rhs> counted{f, evaluations};
            const long n = static_cast<long>(count);
            const double dt = (t1 - t0) / count;
            Vec<N> y = y0;
            for (long k = 0; k < n; ++k) y = rk4_step(counted, t0 + static_cast<double>(k) * dt, y, dt);
            return WorkRun<N>{y, evaluations, n, 0L};
          }};
}

/// Every method of chapter 4's work-precision diagram, at rtol = atol = 10⁻³ … 10⁻¹² from h0: the
/// kit's DOPRI5, the student's Cash–Karp and Bogacki–Shampine (to 10⁻⁸), GSL's rkck, rkf45 and
/// rk8pd, Boost.Odeint's dopri5, fixed-step RK4 (3·10³ … 10⁶ steps), and step doubling over
/// Euler (to 10⁻⁷) and RK2 (to 10⁻¹⁰). The lower orders stop early: their cost explodes.
template <int N, class Rhs>
std::vector<WorkMethod<N>> every_work_method(const Rhs& f, double t0, const Vec<N>& y0, double t1,
                                             double h0) {
  const std::vector<double> tol = decades(3, 12);
  const auto to = [&](int last) { return std::vector<double>(tol.begin(), tol.begin() + last); };
  return {
      chapter_dopri5_method(f, t0, y0, t1, h0, tol),
      embedded_pair_method(cash_karp(), look::cash_karp + " pt 5", f, t0, y0, t1, h0, tol),
      embedded_pair_method(bogacki_shampine(), look::bogacki_shampine + " pt 9", f, t0, y0, t1, h0, to(6)),
      gsl_method(GslStepper::rkck, f, t0, y0, t1, h0, tol),
      gsl_method(GslStepper::rkf45, f, t0, y0, t1, h0, tol),
      gsl_method(GslStepper::rk8pd, f, t0, y0, t1, h0, tol),
      boost_dopri5_method(f, t0, y0, t1, h0, tol),
      fixed_rk4_method(f, t0, y0, t1, {3e3, 1e4, 3e4, 1e5, 3e5, 1e6}),
      step_doubling_method(DoublingBase::euler, f, t0, y0, t1, h0, to(5)),
      step_doubling_method(DoublingBase::midpoint, f, t0, y0, t1, h0, to(8))};
}

/// The methods of every_work_method whose exercises are written: each is tried once at its loosest
/// tolerance, and the report names every other one and the exercise it waits for.
template <int N, class Rhs>
std::vector<WorkMethod<N>> all_work_methods(Report& report, const Rhs& f, double t0, const Vec<N>& y0,
                                            double t1, double h0) {
  std::vector<WorkMethod<N>> written;
  const ProgressWeight uncounted(0);  // the probes are not the diagram's work (progress.hpp)
  for (auto& method : every_work_method(f, t0, y0, t1, h0))
    if (report.attempt(method.label, [&] { method.run(method.tolerances.front()); }))
      written.push_back(std::move(method));
  return written;
}

}  // namespace kit
