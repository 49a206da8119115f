#pragma once
// Explicit (forward) Euler, in the lecture's two forms:
//  - the direct loop on any right-hand side ("Résolution numérique directe");
//  - the matrix form for u' = A u + b ("Résolution explicite").
// Order 1: local (one-step) error O(Δt²), global error at a fixed time O(Δt) (ERRATA item 2).
#include <kit/base/not_implemented.hpp>
#include <kit/problems/affine_system.hpp>

namespace kit {

/// One explicit Euler step of u' = f(t, u):  u_{k+1} = u_k + Δt · f(t_k, u_k).
/// f is evaluated exactly once, at the start of the step.
/// Shapes: u is an Eigen vector; f(t, u) returns a vector of the same shape. t, Δt in s.
template <class Rhs, class State>
State explicit_euler_step(const Rhs& f, typename State::Scalar t, const State& u, typename State::Scalar dt) {
  // TODO(ex 1.1): evaluate f once at (t, u), then move along that slope for Δt
  throw kit::NotImplemented("ex 1.1", "explicit_euler.hpp");
}

/// Explicit Euler on u' = A u + b in matrix form:  u_{k+1} = (I + Δt A) u_k + Δt b.
/// The step matrix I + Δt A is built once for a given Δt; a step is then one mat-vec.
template <int N, class Scalar = double>
class ExplicitEulerAffine {
 public:
  ExplicitEulerAffine(const AffineSystem<N, Scalar>& system, Scalar dt) {
    // TODO(ex 1.2): keep the step matrix I + Δt·A and the constant term Δt·b
    throw kit::NotImplemented("ex 1.2", "explicit_euler.hpp");
  }

  /// u_{k+1} from u_k.
  Vec<N, Scalar> step(const Vec<N, Scalar>& u) const {
    // TODO(ex 1.2): apply the step matrix and add the constant term
    throw kit::NotImplemented("ex 1.2", "explicit_euler.hpp");
  }

 private:
  Mat<N, Scalar> step_matrix_;  ///< I + Δt A
  Vec<N, Scalar> offset_;       ///< Δt b
};

}  // namespace kit
