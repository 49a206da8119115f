#pragma once
// Chapter 9's figures: the cantilever's convergence, the turned element's ghost forces, the
// spinning plate, the springs' mesh dependence and the cost of accuracy.
#include <map>
#include <string>
#include <vector>

#include <kit/app/figure.hpp>

#include "continuum_experiments.hpp"

namespace kit {

std::string model_style(FemModel model);

/// The cantilever by element count: the tip over Euler–Bernoulli's (with Timoshenko's as a guide),
/// and the distance to each model's own Richardson limit, with the fitted order.
Figure cantilever_figure(const std::map<FemModel, TipConvergence>& models, const FemMaterial& material);
/// The strains and largest nodal forces of one element turned rigidly.
Figure turn_figure(const std::vector<TurnedElement>& sweep);
/// The spinning plate: its largest Green strain and how far it turned, by model.
Figure plate_figure(const std::map<FemModel, PlateRun>& runs, const std::string& integrator);
/// The plate's outline at a few times, linear against St Venant–Kirchhoff: `outlines[model]`
/// holds (t [s], the boundary's (x, y) points [m]) pairs.
using Outline = std::vector<std::pair<double, double>>;
using TimedOutline = std::pair<double, Outline>;
Figure plate_shapes_figure(const std::map<FemModel, std::vector<TimedOutline>>& outlines);
/// The stretched sheet on regular and irregular meshes, FEM and springs.
Figure stretch_figure(const std::map<FemModel, std::vector<StretchRow>>& rows);
/// |tip error| against wall time: each model and solver over the meshes.
Figure trade_figure(const std::vector<std::vector<TipRun>>& series);

}  // namespace kit
