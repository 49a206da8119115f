#pragma once
// Chapter 9's static solve: the sheet's rest state under its loads.
#include <string>

#include <kit/fem/fem_body.hpp>

namespace kit {

/// Newton's method on the free coordinates with a sparse direct solver (LDLᵀ, its ordering found
/// once): each step solves −K Δx = f. A linear model is done after its first step, which the
/// second confirms. Converged when |f| on the free coordinates ≤ tolerance × |loads|, or at
/// round-off: when a step moved no coordinate by more than 1e-9 of the largest in-plane
/// displacement (the forces are sums of element forces up to 1e4 times the loads, computed from
/// absolute positions: below that the steps are noise). Fails on a step that is not finite or a
/// singular K. When the whole load fails (a large deflection, far from the start), it is applied
/// again from rest in 4, 16 and then 64 equal increments, each solved from the last: a
/// continuation along the load.
struct StaticSolve {
  int iterations = 0;   ///< Newton steps, over every increment
  int increments = 1;   ///< the load steps of the attempt that is reported
  double residual = 0;  ///< load_residual at the end
  bool converged = false;
  std::string failure;  ///< why not, when not
};
StaticSolve solve_static(FemBody& body, int max_iterations = 40, double tolerance = 1e-10);

}  // namespace kit
