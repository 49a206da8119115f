#pragma once
// Chapter 7's tables: each prints its rows and stores them in the --json summary.
#include <vector>

#include <kit/app/report.hpp>

#include "cloth_implicit_experiments.hpp"

namespace kit {

void print_stiffness_table(Report& report, const std::vector<StiffnessRow>& rows, double h);
void print_trade_table(Report& report, const Trade& trade);
void print_solver_table(Report& report, const std::vector<SolverPoint>& points);
/// The scene run's implicit counts (nothing when it ran an explicit integrator).
void print_implicit_work(Report& report, const ClothRecording& rec);

}  // namespace kit
