#pragma once
// The figures that compare the fixed-step schemes of scheme.hpp (chapter 3), each scheme in its
// one style (look.hpp): error at T against Δt, error against evaluations, and energy drift.
#include <map>
#include <vector>

#include <kit/app/figure.hpp>
#include <kit/ode/convergence_sweep.hpp>
#include <kit/ode/energy_drift.hpp>
#include <kit/ode/scheme.hpp>

namespace kit {

/// |x_N − x(T)| [m] against Δt [s], log-log: each slope is an order, given in the legend.
Figure convergence_figure(const std::map<Scheme, ConvergenceSweep>& sweeps, double t);
/// |x_N − x(T)| [m] against right-hand-side evaluations, log-log, with each target error [m] dotted.
Figure work_figure(const std::map<Scheme, ConvergenceSweep>& sweeps, const std::vector<double>& targets);
/// |E/E0 − 1| against t [s] over `periods` periods at ω·Δt = 0.1, on [1e-8, 1e3]; a curve
/// that leaves that range says so in the legend.
Figure energy_figure(const std::map<Scheme, EnergyDrift>& drifts, long periods);

}  // namespace kit
