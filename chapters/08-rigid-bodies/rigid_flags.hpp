#pragma once
// Chapter 8's flags: the body, the integrator of the scene run, the step, the duration, the
// initial spin, and the ground's restitution and friction.
#include <string>
#include <vector>

#include <kit/app/chapter_app.hpp>
#include <kit/rigid/rigid_contact.hpp>
#include <kit/rigid/rigid_stepper.hpp>

namespace kit {

struct RigidFlags {
  std::string body = "t-handle";
  std::string integrator = "rk4";
  double dt = 1e-3;                 ///< [s]
  double t_end = 10;                ///< [s], the free body's run
  std::string omega0 = "10,0,0.1";  ///< ω in the body frame at t = 0 [rad/s], "x,y,z"
  double restitution = 0.5;
  double friction = 0.3;
  long frames = 120;             ///< pictures and meshes of each scene run
  long trade_steps = 1'000'000;  ///< the most steps an integrator takes in the trade
};

/// Adds --body --integrator --dt --t-end --omega0 --restitution --friction --frames --trade-steps,
/// and the common --fail-on-divergence and --no-viewer.
void add_rigid_flags(ChapterApp& app, RigidFlags& flags);

/// What the flags ask for, checked: the shape, the integrator, ω0 and the contact.
struct RigidSetup {
  RigidShape shape;
  RotationIntegrator integrator{};
  Vec3 omega0 = Vec3::Zero();  ///< [rad/s], body frame
  GroundContact contact;
  double dt = 0, t_end = 0;  ///< [s]
  long frames = 0;
  std::vector<long> trade_steps;  ///< 100, 300, 1000, … up to --trade-steps
};

/// Throws UsageError naming the flag, the value and what is allowed (--omega0 not three finite
/// numbers of at most 1e4 rad/s, or all zero; a step longer than the run).
RigidSetup rigid_setup(const RigidFlags& flags);

/// How long the scene's drop lasts [s]: the box comes to rest within it.
inline constexpr double scene_drop_seconds = 3.0;

/// "--body t-handle, --integrator rk4, --dt 0.001 s, --t-end 10 s": the flags of an estimate.
std::string describe_rigid_run(const RigidFlags& flags);

}  // namespace kit
