#include <kit/ode/reference_solver.hpp>

#include <cmath>
#include <exception>
#include <utility>

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

namespace kit {

namespace {
const gsl_odeiv2_step_type* step_type(GslStepper stepper) {
  switch (stepper) {
    case GslStepper::rk8pd:
      return gsl_odeiv2_step_rk8pd;
    case GslStepper::rkck:
      return gsl_odeiv2_step_rkck;
    case GslStepper::rkf45:
      return gsl_odeiv2_step_rkf45;
    case GslStepper::rk4:
      return gsl_odeiv2_step_rk4;
    case GslStepper::rk2:
      return gsl_odeiv2_step_rk2;
  }
  throw std::invalid_argument("unknown GSL stepper");
}
}  // namespace

struct GslSolver::Impl {
  std::size_t dim;
  Rhs f;
  GslOptions options;
  long rhs_evals = 0;
  std::exception_ptr pending;  // an exception thrown by f, carried across GSL's C frames
  bool non_finite = false;
  gsl_odeiv2_system system{};
  gsl_odeiv2_driver* driver = nullptr;

  // GSL calls this; it must not throw through C code.
  static int evaluate(double t, const double y[], double dydt[], void* self) {
    auto* impl = static_cast<Impl*>(self);
    ++impl->rhs_evals;
    try {
      impl->f(t, y, dydt);
    } catch (...) {
      impl->pending = std::current_exception();
      return GSL_EBADFUNC;
    }
    for (std::size_t i = 0; i < impl->dim; ++i) {
      // GSL's error control would otherwise accept a NaN step (max(NaN, r) ignores it).
      if (!std::isfinite(dydt[i])) {
        impl->non_finite = true;
        return GSL_EBADFUNC;
      }
    }
    return GSL_SUCCESS;
  }
};

GslSolver::GslSolver(std::size_t dim, Rhs f, GslOptions options) : impl_(std::make_unique<Impl>()) {
  gsl_set_error_handler_off();  // report through return codes, never abort()
  impl_->dim = dim;
  impl_->f = std::move(f);
  impl_->options = options;
  impl_->system = {&Impl::evaluate, nullptr, dim, impl_.get()};
  impl_->driver = gsl_odeiv2_driver_alloc_standard_new(&impl_->system, step_type(options.stepper), options.h0,
                                                       options.atol, options.rtol, 1.0, 0.0);
  if (!impl_->driver) throw SolverError("GSL could not allocate an odeiv2 driver");
  gsl_odeiv2_driver_set_nmax(impl_->driver, static_cast<unsigned long>(options.max_steps));
}

GslSolver::~GslSolver() {
  if (impl_ && impl_->driver) gsl_odeiv2_driver_free(impl_->driver);
}

void GslSolver::advance(double& t, double* u, double t1) {
  if (t1 == t) return;
  const double t_start = t;
  const int status = gsl_odeiv2_driver_apply(impl_->driver, &t, t1, u);
  if (impl_->pending) std::rethrow_exception(std::exchange(impl_->pending, nullptr));
  if (status == GSL_SUCCESS) return;
  if (impl_->non_finite) {
    throw SolverError(
        fmt::format("GSL {} reference: the right-hand side returned NaN or Inf near t = {:.6g} s",
                    name(impl_->options.stepper), t));
  }
  throw SolverError(fmt::format("GSL {} reference failed between t = {:.6g} s and {:.6g} s, "
                                "stopped at t = {:.6g} s: {}",
                                name(impl_->options.stepper), t_start, t1, t, gsl_strerror(status)));
}

GslStepResult gsl_single_step(const GslSolver::Rhs& f, std::size_t dim, GslStepper stepper, double t,
                              const Eigen::VectorXd& y, double h) {
  gsl_set_error_handler_off();
  struct Context {
    const GslSolver::Rhs* f;
  } context{&f};
  gsl_odeiv2_system system{[](double time, const double u[], double dudt[], void* p) -> int {
                             (*static_cast<Context*>(p)->f)(time, u, dudt);
                             return GSL_SUCCESS;
                           },
                           nullptr, dim, &context};
  gsl_odeiv2_step* step = gsl_odeiv2_step_alloc(step_type(stepper), dim);
  if (!step) throw SolverError("GSL could not allocate a stepper");
  GslStepResult out{y, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dim))};
  Eigen::VectorXd k1(static_cast<Eigen::Index>(dim));
  f(t, y.data(), k1.data());
  const int status =
      gsl_odeiv2_step_apply(step, t, h, out.y.data(), out.error.data(), k1.data(), nullptr, &system);
  gsl_odeiv2_step_free(step);
  if (status != GSL_SUCCESS)
    throw SolverError(fmt::format("GSL {} step failed: {}", name(stepper), gsl_strerror(status)));
  return out;
}

Stats GslSolver::stats() const {
  Stats s;
  s.rhs_evals = impl_->rhs_evals;
  // The evolve object counts every attempt (count) and every rejected one (failed_steps) over
  // the solver's life. The driver's own counter n restarts at each gsl_odeiv2_driver_apply, so
  // with several sample times it would hold the last interval's steps only.
  const gsl_odeiv2_evolve* evolve = impl_->driver->e;
  s.steps = static_cast<long>(evolve->count - evolve->failed_steps);
  s.rejected = static_cast<long>(evolve->failed_steps);
  return s;
}

}  // namespace kit
