// A sprite animation priced from its counts (sprite_estimate.hpp).
#include <kit/sprites/sprite_estimate.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include <kit/sprites/particle_update.hpp>
#include <kit/sprites/particles.hpp>

namespace kit {
namespace {
// Per-particle-step and per-pixel costs [s]: conservative constants for a 2020s core (the
// update moves 64 B a particle-step; a frame's pixels are cleared, blended and PNG-encoded).
constexpr double seconds_per_particle_step = 5e-9;
constexpr double seconds_per_sprite = 2e-7;
constexpr double seconds_per_blend = 3e-9;     // one pixel of one sprite
constexpr double seconds_per_emission = 2e-7;  // one particle drawn by ex 5.1 and stored
constexpr double seconds_per_pixel = 4e-8;     // one pixel of the frame: cleared, encoded, written
}  // namespace

RunEstimate estimate_sprite_run(const SpriteScene& scene, const SpriteRunOptions& options) {
  const std::vector<double> rate = emissions_per_frame(scene);
  const double alive = expected_alive(scene, options), pixels = double(options.width) * options.height;
  double emitted = 0, wanted = 0, blended = 0;
  const double focal = 0.5 * options.height / std::tan(scene.camera.fov_deg * M_PI / 360.0);
  for (std::size_t i = 0; i < rate.size(); ++i) {
    const Emitter& e = scene.emitters[i];
    emitted += rate[i];
    const double share = rate[i] * e.lifetime.mean * options.fps;  // this emitter's alive, uncapped
    wanted += share;
    // A sprite's area on screen, seen from the camera's distance to its emitter (capped at the image).
    const double distance =
        std::hypot(e.position[0] - scene.camera.position[0], e.position[1] - scene.camera.position[1],
                   e.position[2] - scene.camera.position[2]);
    const double edge = e.size.mean * focal / std::max(distance, 0.05);
    blended += share * std::min(edge * edge + 1.0, pixels);
  }
  if (wanted > alive) blended *= alive / wanted;  // the store is full: fewer sprites than wanted
  // Each frame's emission loop stops at its first refused particle: at most max_particles draws.
  emitted = std::min(emitted, double(options.max_particles) + double(rate.size()));
  const bool render = !options.frame_dir.empty();
  RunEstimate estimate;
  const double frames = double(options.frames + options.warmup_frames);
  estimate.steps = frames;
  estimate.unit = "frames";
  const double render_share = double(options.frames) / frames;
  estimate.seconds_per_step =
      alive * seconds_per_particle_step + emitted * seconds_per_emission +
      (render ? (alive * seconds_per_sprite + blended * seconds_per_blend + pixels * seconds_per_pixel) *
                    render_share
              : 0.0);
  // The arrays, the renderer's sprite lists and the deaths of a frame; the frame, the frames kept
  // for the contact sheet, the sheet itself and its 8-bit copy; the textures.
  estimate.bytes =
      double(options.max_particles) * double(Particles::bytes_per_particle + 40 + sizeof(Death)) +
      (render ? pixels * 12.0 * (1 + 2 * options.sheet_frames) + pixels * 3.0 * options.sheet_frames +
                    options.texture_bytes
              : 0.0);
  return estimate;
}

}  // namespace kit
