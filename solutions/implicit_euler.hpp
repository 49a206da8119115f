#pragma once
// Implicit (backward) Euler for u' = A u + b ("Résolution implicite"):
//   (u_{k+1} − u_k)/Δt = A u_{k+1} + b   ⇔   (I − Δt A) u_{k+1} = u_k + Δt b.
// Order 1 like explicit Euler, but each step solves a linear system: the price of stability.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <kit/base/not_implemented.hpp>
#include <kit/problems/affine_system.hpp>

namespace kit {

template <int N, class Scalar = double>
class ImplicitEulerAffine {
 public:
  /// Factorises I − Δt A once (LU with partial pivoting); every step reuses it.
  /// Throws std::domain_error when I − Δt A is singular (Δt = 1/λ for an eigenvalue λ of A).
  ImplicitEulerAffine(const AffineSystem<N, Scalar>& system, Scalar dt) {
    // BEGIN SOLUTION ex 1.3: factorise I − Δt·A once, and keep Δt·b
    lu_.compute(Mat<N, Scalar>::Identity(system.A.rows(), system.A.cols()) - dt * system.A);
    offset_ = dt * system.b;
    // END SOLUTION
    if (!(lu_.rcond() > std::numeric_limits<Scalar>::epsilon()))
      throw std::domain_error("implicit Euler: I - dt*A is singular for this time step");
  }

  /// u_{k+1} = (I − Δt A)^{-1} (u_k + Δt b).
  Vec<N, Scalar> step(const Vec<N, Scalar>& u) const {
    // BEGIN SOLUTION ex 1.3: one solve with the stored factorisation
    return lu_.solve(u + offset_);
    // END SOLUTION
  }

 private:
  Eigen::PartialPivLU<Mat<N, Scalar>> lu_;  ///< factors of I − Δt A
  Vec<N, Scalar> offset_;                   ///< Δt b
};

}  // namespace kit
