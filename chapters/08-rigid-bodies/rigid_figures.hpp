#pragma once
// Chapter 8's figures: the flips of ω in the body frame, the drift of E and |L|, how far R leaves
// the rotations, the three principal axes' stability, the error in R against its cost, and the drops.
#include <string>
#include <vector>

#include <kit/app/figure.hpp>

#include "rigid_drop.hpp"
#include "rigid_experiments.hpp"

namespace kit {

/// One colour per integrator, the same in every figure.
std::string rigid_style(RotationIntegrator integrator);

/// "flips": ω along the intermediate axis against time, one panel per integrator, with the
/// reference's flip times (GSL) as guides.
Figure rigid_flips_figure(const std::vector<RotationRun>& runs, const RigidShape& shape,
                          const std::vector<double>& reference_flips);
/// "drift": relative drift of E and of |L| against time (log scale, |drift|).
Figure rigid_drift_figure(const std::vector<RotationRun>& runs, const std::string& body);
/// "orthonormality": ‖RᵀR − I‖ against time.
Figure rigid_orthonormality_figure(const std::vector<RotationRun>& runs, const std::string& body);
/// "axes": the spins about the three principal axes, side by side.
Figure rigid_axes_figure(const std::vector<AxisSpin>& spins, const std::string& body);
/// "trade-timing": ‖R − R_ref‖ at T against wall time, each integrator over its steps.
Figure rigid_trade_figure(const RotationTrade& trade, const std::string& body);
/// "drop" (or another name): the centre's height, the lowest corner and the energy against time.
Figure rigid_drop_figure(const std::string& name, const std::string& what, const DropRun& run,
                         const GroundContact& contact, double drop_height);

}  // namespace kit
