#pragma once
// What a sprite animation costs before it starts, from its counts (Little's law: alive ≈
// emission rate × lifetime; app/run_estimate.hpp: how a chapter announces it).
#include <kit/app/run_estimate.hpp>
#include <kit/sprites/sprite_run.hpp>

namespace kit {

/// The run's cost: frames as steps; time from the expected particle-steps, emissions, sprites,
/// sprite pixels (each sprite's size seen from the camera's distance to its emitter) and frame
/// pixels; memory from max_particles, the images kept and the textures.
RunEstimate estimate_sprite_run(const SpriteScene& scene, const SpriteRunOptions& options);

}  // namespace kit
