#pragma once
// The production Dormand–Prince 5(4) integrator, following the structure of Hairer's dopri5.f
// (Hairer, Nørsett & Wanner, Solving ODEs I, II.5 and II.6): FSAL stages, the RMS error norm
// with sk = atol + rtol·max(|y_n|, |y_{n+1}|), the PI law of Hairer's dopri5.f (pi_step_control.hpp), no
// growth right after a rejection, HINIT for the first step, Shampine's dense output, a step budget and a
// minimum step. Two things it does that GSL and Boost.Odeint do not: a right-hand side that returns NaN or
// Inf makes the step rejected and shrunk, never accepted; and every failure is a status with a message, never
// an abort.
//
// Templated on a fixed-size state: no heap allocation per step, no std::function. On a small
// system a step is bound by latency, not flops: the next step cannot start before h_new is
// known. Hence stages that add their newest slope last, an error norm with no sqrt, and a
// step-size law without log or exp on that path (pi_step_control.hpp). `./kit bench adaptive`
// times a step against Boost.Odeint's dopri5 and GSL's rkck in the same run.
#include <cmath>
#include <limits>
#include <type_traits>

#include <fmt/format.h>

#include <kit/app/progress.hpp>
#include <kit/base/state.hpp>
#include <kit/ode/adaptive_run.hpp>
#include <kit/ode/dopri5_coefficients.hpp>
#include <kit/ode/pi_step_control.hpp>

namespace kit {

struct Dopri5Options {
  double rtol = 1e-6;          ///< relative tolerance per component
  double atol = 1e-6;          ///< absolute tolerance per component, units of y
  double h0 = 0.0;             ///< first trial step [s]; 0 lets HINIT choose
  double h_max = 0.0;          ///< largest step [s]; 0 means |t_end − t0|
  long max_steps = 1'000'000;  ///< attempts (accepted + rejected) before too_many_steps
  PiController control;        ///< β = 0.04, safety 0.9, factor in [0.2, 10]
};

/// The continuous extension of one accepted step, valid on [t_old, t_old + h].
template <int N>
struct Dopri5Dense {
  double t_old = 0, h = 0;
  Vec<N> r1, r2, r3, r4, r5;
  /// y(t), fourth order on the step (Shampine's interpolant).
  Vec<N> operator()(double t) const {
    const double theta = (t - t_old) / h, theta1 = 1.0 - theta;
    return r1 + theta * (r2 + theta1 * (r3 + theta * (r4 + theta1 * r5)));
  }
};

/// Passed as on_step when nobody watches the steps: the dense output is then not computed.
struct NoObserver {
  template <class... Args>
  void operator()(const Args&...) const {}
};

template <int N>
struct Dopri5Result {
  double t = 0;
  Vec<N> y;
  Stats stats;  ///< rhs_evals counts every call of f; steps = accepted; rejected
  RunStatus status = RunStatus::finished;
  std::string message;
};

namespace dopri5_coefficients {  // rounded once from the exact fractions of dopri5_coefficients.hpp
namespace F = dopri5_fraction;
inline constexpr double c2 = F::c[1].to_double(), c3 = F::c[2].to_double(), c4 = F::c[3].to_double(),
                        c5 = F::c[4].to_double();
inline constexpr double a21 = F::a[1][0].to_double();
inline constexpr double a31 = F::a[2][0].to_double(), a32 = F::a[2][1].to_double();
inline constexpr double a41 = F::a[3][0].to_double(), a42 = F::a[3][1].to_double(),
                        a43 = F::a[3][2].to_double();
inline constexpr double a51 = F::a[4][0].to_double(), a52 = F::a[4][1].to_double(),
                        a53 = F::a[4][2].to_double(), a54 = F::a[4][3].to_double();
inline constexpr double a61 = F::a[5][0].to_double(), a62 = F::a[5][1].to_double(),
                        a63 = F::a[5][2].to_double(), a64 = F::a[5][3].to_double(),
                        a65 = F::a[5][4].to_double();
inline constexpr double a71 = F::a[6][0].to_double(), a73 = F::a[6][2].to_double(),
                        a74 = F::a[6][3].to_double(), a75 = F::a[6][4].to_double(),
                        a76 = F::a[6][5].to_double();
inline constexpr double e1 = F::e(0).to_double(), e3 = F::e(2).to_double(), e4 = F::e(3).to_double(),
                        e5 = F::e(4).to_double(), e6 = F::e(5).to_double(), e7 = F::e(6).to_double();
inline constexpr double d1 = F::d[0].to_double(), d3 = F::d[2].to_double(), d4 = F::d[3].to_double(),
                        d5 = F::d[4].to_double(), d6 = F::d[5].to_double(), d7 = F::d[6].to_double();
}  // namespace dopri5_coefficients

/// Hairer's HINIT: a first step from the sizes of y0, f0 and an estimate of the second
/// derivative, for a method of order `order`. Costs one evaluation of f.
template <int N, class Rhs>
double dopri5_initial_step(const Rhs& f, double t0, const Vec<N>& y0, const Vec<N>& f0, double h_max,
                           const Dopri5Options& o, long& evaluations) {
  const Vec<N> sk = (o.atol + o.rtol * y0.array().abs()).matrix();
  const double dnf = (f0.array() / sk.array()).square().sum(), dny = (y0.array() / sk.array()).square().sum();
  double h = (dnf <= 1e-10 || dny <= 1e-10) ? 1e-6 : std::sqrt(dny / dnf) * 0.01;
  h = std::min(h, h_max);
  const Vec<N> f1 = f(t0 + h, (y0 + h * f0).eval());
  ++evaluations;
  const double der2 = std::sqrt(((f1 - f0).array() / sk.array()).square().sum()) / h;
  const double der12 = std::max(std::abs(der2), std::sqrt(dnf));
  const double h1 = der12 <= 1e-15 ? std::max(1e-6, h * 1e-3) : std::pow(0.01 / der12, 1.0 / 5.0);
  return std::min({100 * h, h1, h_max});
}

/// Integrates y' = f(t, y) from (t0, y0) to t_end (> t0). After every accepted step it calls
/// on_step(dense, y_new, err), where dense interpolates the step; on_reject(t, h) after every
/// rejected one.
template <int N, class Rhs, class OnStep, class OnReject>
Dopri5Result<N> dopri5(const Rhs& f, double t0, const Vec<N>& y0, double t_end, const Dopri5Options& options,
                       OnStep&& on_step, OnReject&& on_reject) {
  using namespace dopri5_coefficients;
  Dopri5Result<N> out;
  out.t = t0;
  out.y = y0;
  PiStepControl control(options.control, int(y0.size()));
  const double h_max = options.h_max > 0 ? options.h_max : std::abs(t_end - t0);
  const double uround = std::numeric_limits<double>::epsilon();
  if (out.message = unreachable_tolerance(options.rtol, options.atol); !out.message.empty()) {
    out.status = RunStatus::unreachable;
    return out;
  }
  Vec<N> k1 = f(t0, y0), k2, k3, k4, k5, k6, k7, y1, ysti;
  out.stats.rhs_evals = 1;
  double h = options.h0 > 0 ? std::min(options.h0, h_max)
                            : dopri5_initial_step(f, t0, y0, k1, h_max, options, out.stats.rhs_evals);
  double& t = out.t;
  Vec<N>& y = out.y;
  Vec<N> a21_k1 = a21 * k1;
  bool reject = false, last = false, poisoned = false;
  for (;;) {
    if (out.stats.steps + out.stats.rejected >= options.max_steps) {
      out.status = RunStatus::too_many_steps;
      out.message = fmt::format("more than {} steps needed; stopped at t = {:.6g}", options.max_steps, t);
      return out;
    }
    if (((out.stats.steps + out.stats.rejected) & 4095) == 4095) progress_add(4096);  // progress.hpp
    // Below ten rounding units of t the step no longer moves t: the tolerance is out of reach.
    if (0.1 * std::abs(h) <= std::max(std::abs(t), std::abs(t_end - t0)) * uround) {
      out.status = RunStatus::step_too_small;
      out.message = poisoned
                        ? fmt::format("the right-hand side returned NaN or Inf near t = {:.6g}; the step was "
                                      "rejected and shrunk to h = {:.3g} without recovering",
                                      t, h)
                        : fmt::format("step size too small, h = {:.3g} at t = {:.6g}: the solution changes "
                                      "faster than rtol = {:.3g}, atol = {:.3g} can follow (a singularity?)",
                                      h, t, options.rtol, options.atol);
      return out;
    }
    if ((t + 1.01 * h - t_end) > 0) {  // land exactly on t_end
      h = t_end - t;
      last = true;
    }
    // Latency, not flops, bounds a step of a small system, and h_new arrives last. So each
    // stage sums the slopes it already has, scales them by h, and adds its newest slope last,
    // with its own h·a: from one evaluation of f to the next is one multiply and one add.
    y1 = y + h * a21_k1;  // a21·k1 was formed while h_new was still being computed
    k2 = f(t + c2 * h, y1);
    y1 = y + (h * a31) * k1 + (h * a32) * k2;
    k3 = f(t + c3 * h, y1);
    y1 = y + h * (a41 * k1 + a42 * k2) + (h * a43) * k3;
    k4 = f(t + c4 * h, y1);
    y1 = y + h * (a51 * k1 + a52 * k2 + a53 * k3) + (h * a54) * k4;
    k5 = f(t + c5 * h, y1);
    ysti = y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4) + (h * a65) * k5;
    const double t_new = t + h;
    k6 = f(t_new, ysti);
    y1 = y + h * (a71 * k1 + a73 * k3 + a74 * k4 + a75 * k5) + (h * a76) * k6;
    k7 = f(t_new, y1);  // FSAL: the next step's k1
    out.stats.rhs_evals += 6;
    const Vec<N> error = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6) + (h * e7) * k7;
    const Vec<N> sk = (options.atol + options.rtol * y.array().abs().max(y1.array().abs())).matrix();
    // n·err² (RMS norm). A NaN or Inf anywhere in k7, y1 or sk reaches it, since e7 ≠ 0: no
    // separate finiteness check is needed (as long as nobody builds with -ffinite-math-only).
    const double sum_of_squares = (error.array() / sk.array()).square().sum();
    if (control.acceptable(sum_of_squares)) {
      const double h_new = control.after_accepted(h, sum_of_squares, h_max, reject);
      control.remember_accepted(sum_of_squares);
      ++out.stats.steps;
      Dopri5Dense<N> dense;
      double err = 0;
      if constexpr (!std::is_same_v<std::decay_t<OnStep>, NoObserver>) {  // only when someone watches
        err = std::sqrt(sum_of_squares / double(y.size()));
        dense.t_old = t;
        dense.h = h;
        dense.r1 = y;
        dense.r2 = y1 - y;
        dense.r3 = h * k1 - dense.r2;
        dense.r4 = dense.r2 - h * k7 - dense.r3;
        dense.r5 = h * (d1 * k1 + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);
      }
      k1 = k7;
      a21_k1 = a21 * k7;
      y = y1;
      t = last ? t_end : t_new;
      poisoned = false;
      on_step(dense, y, err);
      if (last) return out;
      reject = false;
      h = h_new;
    } else {
      // NaN compares false with everything and lands here: a step with a NaN or Inf is
      // never accepted; it is shrunk by the largest factor allowed.
      poisoned = poisoned || !(sum_of_squares < std::numeric_limits<double>::infinity());
      on_reject(t, h);
      ++out.stats.rejected;
      reject = true;
      last = false;
      h = control.after_rejected(h, sum_of_squares);
    }
  }
}

/// The same, without callbacks: the final state only (what the benchmarks time). No dense
/// output is built.
template <int N, class Rhs>
Dopri5Result<N> dopri5(const Rhs& f, double t0, const Vec<N>& y0, double t_end,
                       const Dopri5Options& options) {
  return dopri5(f, t0, y0, t_end, options, NoObserver{}, [](double, double) {});
}

/// The same, recording every accepted and rejected step (what the chapter plots).
template <int N, class Rhs>
AdaptiveRun<Vec<N>> dopri5_run(const Rhs& f, double t0, const Vec<N>& y0, double t_end,
                               const Dopri5Options& options) {
  AdaptiveRun<Vec<N>> run;
  run.accepted.push(t0, y0);
  const auto result = dopri5(
      f, t0, y0, t_end, options,
      [&](const Dopri5Dense<N>& dense, const Vec<N>& y, double) {
        run.accepted.push(dense.t_old + dense.h, y);
        run.step_sizes.push_back(dense.h);
      },
      [&](double t, double h) {
        run.rejected_t.push_back(t);
        run.rejected_h.push_back(h);
      });
  run.stats = result.stats;
  run.status = result.status;
  run.message = result.message;
  return run;
}

}  // namespace kit
