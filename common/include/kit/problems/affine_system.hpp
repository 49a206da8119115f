#pragma once
// The lecture's linear model u' = A u + b ("Approche matricielle").
#include <kit/base/state.hpp>

namespace kit {

/// u'(t) = A u(t) + b, with constant A (N×N, 1/s) and b (N, units of u per s).
/// Free fall and the spring of chapters 1–2 are both of this form.
template <int N, class Scalar = double>
struct AffineSystem {
  Mat<N, Scalar> A;
  Vec<N, Scalar> b;

  /// f(t, u) = A u + b; t is unused because the system is autonomous.
  Vec<N, Scalar> operator()(Scalar /*t*/, const Vec<N, Scalar>& u) const { return A * u + b; }

  /// The same system in another scalar type (float, long double).
  template <class Other>
  AffineSystem<N, Other> cast() const {
    return {A.template cast<Other>(), b.template cast<Other>()};
  }
};

}  // namespace kit
