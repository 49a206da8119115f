#pragma once
// What one step of an embedded Runge–Kutta pair returns (ex 4.2 computes it; embedded_run.hpp
// drives it).
namespace kit {

template <class State>
struct EmbeddedStep {
  State y;              ///< y_{n+1}, from the weights b
  State error;          ///< h Σ (b_i − b̂_i) k_i, the local error estimate, units of y
  State last_stage;     ///< k_s; for an FSAL pair, f(t + h, y_{n+1}), the next step's k_1
  int evaluations = 0;  ///< new evaluations of f (k_1 is given): s − 1
};

}  // namespace kit
