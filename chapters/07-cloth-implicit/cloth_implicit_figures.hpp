#pragma once
// Chapter 7's figures: the stiffness an implicit step survives, the energy it removes, the
// speed/accuracy trade against the explicit methods, and the linear solver's iterations.
#include <string>
#include <vector>

#include <kit/app/figure.hpp>

#include "cloth_implicit_experiments.hpp"

namespace kit {

/// The gnuplot style of each chapter 7 method, by its flag name (the explicit ones keep their
/// chapter 6 colours).
std::string cloth_method_style(const std::string& key);

/// Figure 1: symplectic Euler's largest stable Δt against K, and the implicit methods at h.
Figure cloth_stiffness_figure(const std::vector<StiffnessRow>& rows, double h, const std::string& scene);

/// Figure 2: the energy each implicit method removes by t_end, against h.
Figure cloth_damping_figure(const Trade& trade, const std::string& scene);

/// Figure 3: RMS node-position error at t_end against wall time, every method over its steps.
Figure cloth_trade_figure(const Trade& trade, const std::string& scene);

/// Figure 4: mean CG iterations per solve against h, at each K, for both solvers.
Figure cloth_solver_figure(const std::vector<SolverPoint>& points, const std::string& scene);

}  // namespace kit
