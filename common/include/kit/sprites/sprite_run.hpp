#pragma once
// A whole sprite animation (chapter 5): the scene run frame by frame, its counts and a sample of
// particle paths recorded, each frame rendered and written as a PNG when asked. What it would
// cost is estimated from its counts before it starts (sprite_estimate.hpp).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <kit/render/animation.hpp>
#include <kit/render/frame_writer.hpp>
#include <kit/render/image.hpp>
#include <kit/render/web_page.hpp>
#include <kit/sprites/sprite_renderer.hpp>
#include <kit/sprites/sprite_system.hpp>

namespace kit {

struct SpriteRunOptions {
  long frames = 120;       ///< rendered frames
  long warmup_frames = 0;  ///< run before them, counted but not rendered
  double fps = 30;         ///< [1/s]
  std::uint64_t seed = 1;
  Integrator integrator = Integrator::exact;
  long max_particles = 100000;
  int width = 640, height = 360;    ///< [px]
  std::filesystem::path frame_dir;  ///< empty: no frames rendered nor written
  CompositeOver over = nullptr;     ///< ex 5.3, or nullptr for the renderer's own
  int paths = 24;                   ///< particles whose paths are recorded
  int sheet_frames = 12;            ///< frames kept for the contact sheet, evenly spaced
  double texture_bytes = 0;         ///< what the emitters' textures take, for the estimate [B]
  /// Particles kept a rendered frame for the 3D page (every k-th alive one), at most
  /// page_particle_frames / frames of them; 0: no page.
  long page_particles = 0;
};
/// Particle-frames the 3D page keeps in all: 2e6 take 56 MB while the run lasts.
inline constexpr long page_particle_frames = 2'000'000;

/// One particle's recorded path, a point per frame it was alive (after that frame's update).
struct ParticlePath {
  std::uint32_t id = 0;
  std::vector<double> x, y, z;  ///< [m]
  std::vector<double> age;      ///< [s]
};

struct SpriteRecording {
  std::vector<FrameCounts> frames;  ///< one per frame run, warm-up frames first
  SpriteTotals totals;
  UpdateWork work;
  RenderStats render;  ///< summed over the frames rendered
  std::vector<ParticlePath> paths;
  FrameSequence rendered;  ///< the frames written, with those kept for the contact sheet
  long warmup_frames = 0;  ///< the first frames, run but not rendered
  long peak_alive = 0;
  long diverged_at = -1;  ///< first frame with a non-finite position, or −1
  PagePoints page;        ///< the particles kept for the 3D page, rendered frames only
};

/// Mean particles each emitter adds a frame at steady state: its rate, or for a burst emitter,
/// its rate per burst times the deaths a frame of the emitters that burst into it.
std::vector<double> emissions_per_frame(const SpriteScene& scene);
/// Particles alive at steady state, by Little's law: Σ over emitters of particles a frame ×
/// mean lifetime [s] × fps, at most max_particles.
double expected_alive(const SpriteScene& scene, const SpriteRunOptions& options);
/// What a recording's frames become in `out` (finish_animation): contact_sheet.png (the kept
/// frames, 4 a row), animation.mp4 and .gif (ffmpeg, when installed) and play.gp (a gnuplot
/// player). Nothing when no frame was rendered (a run that diverged before its first frame).
/// The run as a 3D page: its kept particles as points with their colour and opacity, and at each
/// frame the particles alive, emitted and shown.
WebPage sprite_page(const SpriteScene& scene, const SpriteRecording& rec, const SpriteRunOptions& options);

std::optional<AnimationOutputs> write_animation(const SpriteRecording& recording,
                                                const SpriteRunOptions& options,
                                                const std::filesystem::path& out);

/// Runs `scene` for options.frames frames with the student's kernels. Reports one unit of
/// progress per frame. Stops early, and says so in diverged_at, when a position becomes
/// non-finite: the frames so far are kept.
SpriteRecording run_sprite_scene(const SpriteScene& scene, const SpriteRunOptions& options,
                                 SpriteKernels kernels);

}  // namespace kit
