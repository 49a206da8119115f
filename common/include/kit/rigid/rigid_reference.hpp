#pragma once
// The reference for chapter 8: the torque-free rotation integrated by GSL's rk8pd on the body-
// frame equations (q, L_b) of rigid_integrators.hpp, at a tolerance of 1e-13; q is normalised
// only when a sample is read.
#include <vector>

#include <kit/ode/reference_solver.hpp>
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// The states at each of `times` [s] (ascending, from 0) of the body started in `start`, moving
/// without torque (x and P left as they are). `stats` receives GSL's counts.
std::vector<RigidState> free_rotation_reference(const RigidShape& shape, const RigidState& start,
                                                const std::vector<double>& times, Stats* stats = nullptr);

}  // namespace kit
