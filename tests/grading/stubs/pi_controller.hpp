#pragma once
// The judge's pi_controller.hpp (ex 4.3): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/ode/pi_law.hpp>

#include "remote/fields/pi_law.hpp"
#include "remote/judge.hpp"

namespace kit {
inline double pi_step_factor(const PiController& c, double err) {
  return remote::call<double>("pi_step_factor", c, err);
}
}  // namespace kit
