#pragma once
// Chapter 8's scene runs as 3D pages (web_page.hpp): the tumbling body under the lecture's
// first-order steps and the implicit midpoint side by side on one clock, each with its cost, so
// that the drift of the flips is watched; and the dropped box on the ground.
#include <string>
#include <vector>

#include <kit/render/page_output.hpp>
#include <kit/rigid/rigid_body.hpp>
#include <kit/rigid/rigid_stepper.hpp>

#include "rigid_drop.hpp"
#include "rigid_flags.hpp"

namespace kit {

/// A body's states as a pane: its boxes' faces as a flat-shaded mesh (two triangles a face), the
/// ground when `ground`, and at each state its rotational energy, |L| and ‖RᵀR − I‖.
PagePane rigid_pane(const RigidShape& shape, const std::vector<RigidState>& frames, const std::string& label,
                    bool ground);

/// out_dir/<shape>.html: the body tumbling for --t-end at --dt with explicit Euler on R, Euler on
/// q, the exponential map and the implicit midpoint (those of `integrators`: the ones the
/// student's methods provide); out_dir/drop.html: `drop` (the box dropped tilted, at
/// `integrator`), lasting `drop_seconds` [s].
void write_rigid_pages(ChapterApp& app, const RigidSetup& s, const RigidKernels& kernels,
                       const std::vector<RotationIntegrator>& integrators, const RigidState& start,
                       const DropRun& drop, double drop_seconds);

}  // namespace kit
