#pragma once
// The reference every chapter compares against: GSL's odeiv2 driver (rk8pd by default,
// tight tolerances). GSL failures become kit::SolverError, never an abort.
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <kit/base/enum_names.hpp>
#include <kit/base/state.hpp>

namespace kit {

/// A solver could not finish: the message says where and why.
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The odeiv2 steppers the kit uses, as reference or as peers.
enum class GslStepper { rk8pd, rkck, rkf45, rk4, rk2 };
/// GSL's own names of its steppers.
inline constexpr auto gsl_stepper_names = enum_names<GslStepper>({
    {GslStepper::rk8pd, "rk8pd", "rk8pd"},
    {GslStepper::rkck, "rkck", "rkck"},
    {GslStepper::rkf45, "rkf45", "rkf45"},
    {GslStepper::rk4, "rk4", "rk4"},
    {GslStepper::rk2, "rk2", "rk2"},
});
static_assert(gsl_stepper_names.in_order());
inline const char* name(GslStepper stepper) { return gsl_stepper_names.flag(stepper); }

struct GslOptions {
  GslStepper stepper = GslStepper::rk8pd;
  double rtol = 1e-13;           ///< relative tolerance per step (GSL's eps_rel)
  double atol = 1e-13;           ///< absolute tolerance per step (GSL's eps_abs), units of u
  double h0 = 1e-6;              ///< first trial step [s]
  long max_steps = 100'000'000;  ///< the driver gives up (SolverError) beyond this
};

/// GSL odeiv2 on u' = f(t, u) of run-time dimension. Not a hot path: the right-hand side is a
/// std::function on raw arrays, as GSL wants it.
class GslSolver {
 public:
  /// f(t, u, dudt) writes u'(t) into dudt; both arrays have `dim` entries.
  using Rhs = std::function<void(double t, const double* u, double* dudt)>;

  GslSolver(std::size_t dim, Rhs f, GslOptions options = {});
  ~GslSolver();
  GslSolver(const GslSolver&) = delete;
  GslSolver& operator=(const GslSolver&) = delete;

  /// Integrates from (t, u) to t1, updating both. Throws SolverError when GSL fails or the
  /// right-hand side returns a non-finite value.
  void advance(double& t, double* u, double t1);

  /// Evaluations of f, accepted steps (Stats::steps) and rejected steps, over every advance.
  Stats stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One step of a GSL stepper, as gsl_odeiv2_step_apply computes it with k1 = f(t, y) given.
struct GslStepResult {
  Eigen::VectorXd y;      ///< y_{n+1}
  Eigen::VectorXd error;  ///< GSL's error estimate
};
GslStepResult gsl_single_step(const GslSolver::Rhs& f, std::size_t dim, GslStepper stepper, double t,
                              const Eigen::VectorXd& y, double h);

/// The same on fixed-size states.
template <class System, int N>
GslStepResult gsl_single_step(const System& f, GslStepper stepper, double t, const Vec<N>& y, double h) {
  return gsl_single_step(
      [&f](double time, const double* u, double* dudt) {
        Eigen::Map<Vec<N>> derivative(dudt);
        derivative = f(time, Eigen::Map<const Vec<N>>(u));
      },
      static_cast<std::size_t>(N), stepper, t, Eigen::VectorXd(y), h);
}

/// The reference solution of u' = f(t, u), u(t0) = u0, sampled at each of `times`
/// (ascending, ≥ t0). f is any callable f(t, u) → u' on fixed-size states.
template <class System, int N>
Trajectory<Vec<N>> reference_solution(const System& f, double t0, const Vec<N>& u0,
                                      const std::vector<double>& times, GslOptions options = {},
                                      Stats* stats = nullptr) {
  GslSolver solver(
      static_cast<std::size_t>(N),
      [&f](double t, const double* u, double* dudt) {
        Eigen::Map<Vec<N>> derivative(dudt);
        derivative = f(t, Eigen::Map<const Vec<N>>(u));
      },
      options);
  Trajectory<Vec<N>> samples;
  double t = t0;
  Vec<N> u = u0;
  for (double t1 : times) {
    solver.advance(t, u.data(), t1);
    samples.push(t1, u);
  }
  if (stats) *stats = solver.stats();
  return samples;
}

}  // namespace kit
