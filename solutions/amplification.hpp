#pragma once
// Linear stability (lecture, "Précision/Stabilité"): on the test equation y' = λy, one step of
// a Runge–Kutta-type method multiplies y by R(z), z = λΔt. The method is stable for that λΔt
// when |R(z)| ≤ 1. For the spring, λ are the eigenvalues of A.
#include <complex>
#include <stdexcept>

#include <kit/base/not_implemented.hpp>
#include <kit/ode/scheme.hpp>

namespace kit {

/// R(z) of a scheme. Symplectic Euler treats x and v differently, so it has no scalar R(z);
/// its stability comes from its 2×2 step matrix (chapter 2 reads it off your ex 2.3 step).
inline std::complex<double> amplification_factor(Scheme scheme, std::complex<double> z) {
  if (scheme == Scheme::symplectic_euler)
    throw std::invalid_argument("symplectic Euler has no scalar amplification factor");
  // BEGIN SOLUTION ex 2.4: apply one step of each scheme to y' = λy, y_k = 1, and read off y_{k+1} in terms of z = λΔt
  switch (scheme) {
    case Scheme::explicit_euler:
      return 1.0 + z;
    case Scheme::implicit_euler:
      return 1.0 / (1.0 - z);
    case Scheme::midpoint:
      return 1.0 + z + z * z / 2.0;
    case Scheme::rk4:
      return 1.0 + z * (1.0 + z / 2.0 * (1.0 + z / 3.0 * (1.0 + z / 4.0)));
    default:
      break;
  }
  // END SOLUTION
  throw std::invalid_argument("unknown scheme");
}

}  // namespace kit
