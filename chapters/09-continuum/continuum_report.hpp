#pragma once
// Chapter 9's printed results: every number here goes to the text and the JSON summary alike.
#include <map>
#include <vector>

#include <kit/app/report.hpp>

#include "continuum_experiments.hpp"

namespace kit {

/// The material in plane stress and the cantilever's closed forms.
void print_material(Report& report, const FemMaterial& material);
/// The cantilever's tip by mesh against Euler–Bernoulli, one column a model; each model's
/// Richardson limit against Euler–Bernoulli and Timoshenko, and its fitted order.
void print_cantilever(Report& report, const std::map<FemModel, TipConvergence>& models,
                      const FemMaterial& material);
/// The rigidly turned element at a few angles.
void print_turns(Report& report, const std::vector<TurnedElement>& sweep);
/// The spinning plate's end state, by model.
void print_plate(Report& report, const std::map<FemModel, PlateRun>& runs);
/// The stretched sheet: each model's stretch on both meshes, and their difference.
void print_stretch(Report& report, const std::map<FemModel, std::vector<StretchRow>>& rows);
/// The cost of accuracy: every model and solver by mesh, with its error and wall time.
void print_trade(Report& report, const std::vector<std::vector<TipRun>>& series);

}  // namespace kit
