#pragma once
// What chapter 8 prints: which integrators can run (the lecture's wait for their exercises), the
// drift table, the flips against the step, the axes, the trade and the drops. Every number goes
// through the report layer, so the text and the --json summary agree.
#include <string>
#include <vector>

#include <kit/app/report.hpp>

#include "rigid_drop.hpp"
#include "rigid_experiments.hpp"

namespace kit {

/// summary["body"]: the shape's mass and principal moments, ω0 [rad/s, body frame] and the closed
/// form's time between sign changes of ω along the intermediate axis (`interval` [s], +∞ when two
/// moments are equal: then nothing flips).
void print_body(Report& report, const RigidShape& shape, const Vec3& omega0, double interval);
/// summary["omega"]: ex 8.3's ω = R I⁻¹ Rᵀ L against (R I Rᵀ)⁻¹ L at one orientation, relative.
/// Throws NotImplemented while ex 8.3 waits.
void print_angular_velocity_check(Report& report, const RigidKernels& kernels, const RigidShape& shape);

/// The integrators whose exercises are written: each one tries a step, and the report names
/// the ones that wait ("[skipped] explicit Euler on R: ex 8.1 is not implemented yet …").
std::vector<RotationIntegrator> available_rotation_integrators(Report& report, const RigidKernels& kernels,
                                                               const RigidShape& shape);

/// summary["integrators"][flag]: flips, time between them against the closed form's, the drifts.
void print_drift_table(Report& report, const std::vector<RotationRun>& runs, double closed_form_interval);
/// summary["flip_sweep"]: flips and their interval at each step.
void print_flip_sweep(Report& report, const std::vector<FlipSweepRow>& rows, double closed_form_interval);
/// summary["axes"]: the three spins.
void print_axes(Report& report, const std::vector<AxisSpin>& spins, int intermediate);
/// summary["trade"][flag]: the error at each step count and its wall time.
void print_trade(Report& report, const RotationTrade& trade);
/// summary[section]: bounces, the first rise against e², the deepest corner, friction, energy.
void print_drop(Report& report, const std::string& section, const std::string& what, const DropRun& run,
                const GroundContact& contact, double drop_height, double resting);

/// summary["scene"]: the chosen integrator's tumble (its flips and energy drift) and its drop of
/// the tilted box (its bounces), at step h [s] over t_end [s].
void print_scene_runs(Report& report, RotationIntegrator integrator, double h, const RigidShape& shape,
                      double t_end, const RotationRun& tumble, const DropRun& drop);

}  // namespace kit
