#pragma once
// Chapter 6's tables, printed and stored in the --json summary under their section names.
#include <map>
#include <vector>

#include <kit/app/report.hpp>
#include <kit/cloth/cloth_run.hpp>
#include <kit/cloth/cloth_stability.hpp>

#include "cloth_mesh_dependence.hpp"

namespace kit {

/// "stability": layout, integrator, ω_max, predicted and measured Δt_max, their ratio.
void print_stability_table(Report& report, const std::vector<StabilityCase>& cases);
/// "resolution": N, springs, Δt_max predicted and measured, N·Δt_max, spring forces per second.
void print_resolution_table(Report& report, const std::vector<StabilityAtResolution>& sweep);
/// "integrators": steps, spring forces, energy change, peak stretch, when it exploded.
void print_integrator_table(Report& report, const ClothRuns& runs);
/// "mesh": how the sheet is held, N, drop, peak stretch, steps to rest.
void print_mesh_table(Report& report, const std::map<Hanging, std::vector<Sag>>& sags);

}  // namespace kit
