#pragma once
// Chapter 6's figures: energy and strain over time per integrator, the largest stable step
// measured against its prediction, its 1/N law and the N³ cost, and the hanging sheet's sag
// at several resolutions (the lecture's "dépendance au maillage").
#include <map>
#include <string>
#include <vector>

#include <kit/app/figure.hpp>
#include <kit/cloth/cloth_run.hpp>
#include <kit/cloth/cloth_stability.hpp>

#include "cloth_mesh_dependence.hpp"

namespace kit {

/// The gnuplot style of each cloth integrator (the course's colours for each method).
std::string cloth_style(ClothIntegrator integrator);

/// Total energy minus its start, E(t) − E(0) [J], for each integrator at the scene's Δt: above
/// zero the method adds energy, below it removes some. A run that exploded ends where it did.
Figure cloth_energy_figure(const ClothRuns& runs, double dt, const std::string& scene);

/// The largest structural stretch over time [%], with and without Provot's strain limit.
Figure cloth_strain_figure(const ClothRecording& free, const ClothRecording& limited, double max_strain,
                           const std::string& scene);

/// Measured Δt_max (filled) against the prediction (open) for each layout and integrator.
Figure cloth_stability_figure(const std::vector<StabilityCase>& rows, const std::string& scene);

/// Δt_max against N with the fitted power law, and the force evaluations one simulated second
/// costs, with its fit (1/N and N³ expected).
Figure cloth_resolution_figure(const std::vector<StabilityAtResolution>& rows, const std::string& scene);

/// The hanging sheet's drop at each N, one curve per way of holding it.
Figure cloth_mesh_figure(const std::map<Hanging, std::vector<Sag>>& sags, double limit);

}  // namespace kit
