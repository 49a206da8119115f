#pragma once
// Chapter 7's command line: chapter 6's cloth flags (its scenes), where --integrator also names
// the implicit methods and is one of them by default, plus --solver, --cg-tol, --iterations and
// --no-clamp.
#include <string>

#include "cloth_flags.hpp"

namespace kit {

struct ImplicitFlags {
  std::string solver = "pcg";  ///< cg (Eigen, pins eliminated) or pcg (ex 7.3, filtered)
  double cg_tol = 1e-3;        ///< relative residual of each linear solve
  long iterations = 10;        ///< Liu's local/global iterations; Newton's most iterations
  bool no_clamp = false;       ///< keep (1 − L0/l) < 0 in the stiffness blocks
};

/// The chapter's default step for an implicit method [s] when --dt is not given.
inline constexpr double implicit_default_dt = 1.0 / 30;

/// Adds chapter 6's flags (with --integrator widened to implicit-euler, newton and liu, and the
/// scene "drape" by default), chapter 7's own, --fail-on-divergence and --quick, each range
/// checked when parsed.
void add_implicit_cloth_flags(ChapterApp& app, ClothFlags& cloth, ImplicitFlags& implicit);

/// The scene with chapter 6's overrides; an implicit --integrator leaves the scene's own.
ClothScene apply_implicit_cloth_flags(ClothScene scene, const ClothFlags& cloth);

/// The run the flags ask for: implicit-euler by default at h = 1/30 s, or the named method (an
/// explicit one at the scene's Δt unless --dt says otherwise).
ClothRunOptions implicit_cloth_run(const ClothScene& scene, const ClothFlags& cloth,
                                   const ImplicitFlags& implicit, ImplicitKernels kernels);

/// "--integrator implicit-euler, --dt 0.0333 s, ...": what sets the run's cost.
std::string describe_implicit_run(const ClothScene& scene, const ClothRunOptions& run);

}  // namespace kit
