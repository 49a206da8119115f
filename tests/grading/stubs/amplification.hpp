#pragma once
// The judge's amplification.hpp (ex 2.4): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <complex>

#include <kit/ode/scheme.hpp>

#include "remote/judge.hpp"

namespace kit {
inline std::complex<double> amplification_factor(Scheme scheme, std::complex<double> z) {
  return remote::call<std::complex<double>>("amplification_factor", scheme, z);
}
}  // namespace kit
