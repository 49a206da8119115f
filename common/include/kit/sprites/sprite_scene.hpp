#pragma once
// What a sprite scene is (chapter 5; Reeves 1983): emitters, the forces that act, the rules that
// kill a particle, and the camera. A scene file (sprite_scene_file.hpp) fills these in and lists
// only what the scene uses: an absent force is never computed.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <kit/base/enum_names.hpp>
#include <kit/base/vec3.hpp>
#include <kit/render/camera.hpp>
#include <kit/render/image.hpp>

namespace kit {

using Vec3d = Vec3;  ///< the name before kit/base/vec3.hpp: kept one release for exercise copies that use it

/// Reeves's stochastic attribute: mean + rand·variance with rand uniform in [−1, 1]. Reeves's
/// "variance" is the half-width of that uniform law; its statistical variance is variance²/3.
struct Spread {
  double mean = 0;
  double variance = 0;  ///< half-width, ≥ 0
};

/// Where particles start and which way they go.
enum class EmitterShape {
  point,   ///< at `position`, directions uniform over the whole sphere
  disc,    ///< uniform on a disc of `radius` normal to `axis`, directions within `angle` of `axis`
  sphere,  ///< uniform in a ball of `radius`, directions radial (outward)
  cone,    ///< at `position`, directions uniform in the cap of half-angle `angle` around `axis`
};
/// Their names in scene files (shape = "disc") and messages.
inline constexpr auto emitter_shape_names = enum_names<EmitterShape>({
    {EmitterShape::point, "point", "point"},
    {EmitterShape::disc, "disc", "disc"},
    {EmitterShape::sphere, "sphere", "sphere"},
    {EmitterShape::cone, "cone", "cone"},
});
static_assert(emitter_shape_names.in_order());

/// How a sprite meets the image: "over" (Porter–Duff, sorted back to front) or additive (glows,
/// order-free).
enum class Blend { over, additive };
inline constexpr auto blend_names = enum_names<Blend>({
    {Blend::over, "over", "over"},
    {Blend::additive, "additive", "additive"},
});
static_assert(blend_names.in_order());

struct Emitter {
  std::string name;
  EmitterShape shape = EmitterShape::point;
  Vec3 position{0, 0, 0};  ///< [m]
  Vec3 axis{0, 1, 0};      ///< unit direction (normalised on load)
  double radius = 0;       ///< disc and sphere [m]
  double angle_deg = 0;    ///< disc and cone half-angle [deg], in [0, 180]
  Spread rate;             ///< particles per frame (a fraction rounds up with that probability)
  Spread speed;            ///< initial speed [m/s]
  Spread lifetime{1, 0};   ///< [s]; mean − variance > 0
  Spread size{0.1, 0};     ///< sprite edge [m]
  Colour colour{1, 1, 1};  ///< mean linear RGB in [0, 1]
  Colour colour_variance{0, 0, 0};
  Spread alpha{1, 0};  ///< opacity in [0, 1]
  // Rates of change over a particle's life (Reeves: per frame; here per second, so Δt can vary).
  // Zero means the attribute stays constant and nothing is computed for it.
  Colour colour_rate{0, 0, 0};  ///< [1/s]
  double alpha_rate = 0;        ///< [1/s], negative fades out
  double size_rate = 0;         ///< [m/s]
  Blend blend = Blend::over;
  std::string texture = "soft";  ///< built-in name (soft, spark, flake, smoke) or a PNG path
  /// Emits only in bursts, when a particle of another emitter dies (never per frame).
  bool burst_only = false;
  /// Index of the emitter that bursts where this emitter's particles die (fireworks).
  std::optional<int> on_death;
  double inherit_velocity = 0;     ///< fraction of the dead particle's velocity a burst inherits
  long first_frame = 0;            ///< emits per frame from this frame on
  std::optional<long> last_frame;  ///< … up to and including this one
};

/// The forces of the scene; each one is there only when the scene names it.
struct SpriteForces {
  std::optional<Vec3> gravity;  ///< [m/s²]
  std::optional<double> drag;   ///< linear drag rate k [1/s]: a = −k (v − wind)
  std::optional<Vec3> wind;     ///< [m/s]; acts through drag, so it needs drag
};

/// What kills a particle besides its lifetime.
struct DeathRules {
  std::optional<double> alpha_below;  ///< opacity threshold in [0, 1)
  /// Axis-aligned box [m]; leaving it kills.
  std::optional<std::array<Vec3, 2>> region;
};

/// The largest max_particles a flag or scene file may ask for: a bound on the count, beyond the
/// memory of any machine, not on this machine. The run estimate (sprite_run.hpp) refuses, up
/// front and with the memory it would need, a store this machine cannot hold.
constexpr long max_particles_bound = 1'000'000'000'000;

struct SpriteScene {
  std::string name;
  std::string file;   ///< where it was read from
  long frames = 120;  ///< default for --frames
  double fps = 30;    ///< default for --fps
  /// Seconds simulated before the first frame, so that a scene starts in its steady state
  /// (snow already falling); those frames are counted but not rendered.
  double warmup = 0;
  long max_particles = 100000;  ///< default for --max-particles
  std::vector<Emitter> emitters;
  SpriteForces forces;
  DeathRules death;
  Camera camera;
  Colour background{0.02, 0.02, 0.05};  ///< linear RGB
};

}  // namespace kit
