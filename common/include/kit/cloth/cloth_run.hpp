#pragma once
// A cloth scene run from start to end (chapter 6): its energy and strain sampled over time, its
// positions at the frame times, what was computed, and whether and when it exploded. A diverging
// run is a result: it stops at the first sign and says when.
#include <map>
#include <vector>

#include <optional>
#include <string>

#include <kit/cloth/cloth_implicit_step.hpp>
#include <kit/cloth/cloth_system.hpp>

namespace kit {

struct ClothRunOptions {
  ClothIntegrator integrator = ClothIntegrator::symplectic_euler;
  double dt = 1e-4;          ///< [s]
  double t_end = 1;          ///< [s]
  int frames = 0;            ///< positions kept at t = k·t_end/frames, k = 0 … frames (0: none)
  int samples = 400;         ///< energy and strain samples over [0, t_end]
  bool strain_limit = true;  ///< false: the scene's strain limit is switched off for this run
  /// Chapter 7: set, the run steps with this implicit method instead of `integrator`.
  std::optional<ImplicitMethod> implicit;
  ImplicitSettings implicit_settings;
  ImplicitKernels implicit_kernels;
};

struct ClothSample {
  double t = 0;          ///< [s]
  double kinetic = 0;    ///< [J]
  double potential = 0;  ///< springs and gravity [J]
  double strain = 0;     ///< largest structural stretch (l − L0)/L0
  double total() const { return kinetic + potential; }
};

struct ClothRecording {
  std::vector<ClothSample> samples;
  std::vector<NodeArray> frames;  ///< positions at the frame times, while the cloth holds
  /// At each frame, the contacts so far: nodes pushed out of a collider after a step, and (the
  /// implicit steps) node-steps held on one inside the solve.
  std::vector<long> frame_contacts;
  long steps = 0;
  double exploded_at = -1;  ///< [s]: when the cloth blew up or a solve failed (< 0: never)
  std::string failure;      ///< why an implicit step could not go on (empty: it could)
  double peak_strain = 0;   ///< largest structural stretch measured (every 8 steps)
  double deepest = 0;       ///< deepest a node ever sat inside a collider after a step [m]
  ClothWork work;
  ImplicitWork implicit;    ///< what the implicit steps computed (chapter 7)
  double wall_seconds = 0;  ///< the run's wall time on this machine [s] (shown, never tested)
};

/// A cloth has exploded once a coordinate is not finite or a structural spring is stretched
/// beyond this many times its rest length minus one (1000%).
inline constexpr double exploded_strain = 10.0;

/// Runs `scene` with `springs` (ex 6.2) and `kernels` (ex 6.3, 6.4) as `options` say. Reports
/// one unit of progress per step.
ClothRecording run_cloth(const ClothScene& scene, const Springs& springs, ClothKernels kernels,
                         const ClothRunOptions& options);

/// The scene run once with each of the four integrators; only `options.integrator`'s run keeps
/// its frames.
using ClothRuns = std::map<ClothIntegrator, ClothRecording>;
ClothRuns run_each_integrator(const ClothScene& scene, const Springs& springs, ClothKernels kernels,
                              const ClothRunOptions& options);

/// The super-elastic effect: the same run with and without Provot's strain limit (the scene's,
/// or the default 10% when it has none). `as_run` is the run the scene asked for, reused.
struct StrainComparison {
  ClothRecording free, limited;
  double max_strain = 0;  ///< the limit's relative stretch
};
StrainComparison compare_strain_limit(const ClothScene& scene, const Springs& springs, ClothKernels kernels,
                                      ClothRunOptions options, const ClothRecording& as_run);

/// The deepest any node of x lies inside the scene's ground or spheres [m] (0: none inside),
/// each sphere taken at contact_radius, where the contacts put the nodes.
double deepest_penetration(const ClothScene& scene, const NodeArray& x);

}  // namespace kit
