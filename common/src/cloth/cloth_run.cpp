// A cloth scene run from start to end (cloth_run.hpp).
#include <kit/cloth/cloth_run.hpp>

#include <kit/base/stopwatch.hpp>

#include <algorithm>
#include <cmath>

#include <kit/app/progress.hpp>
#include <kit/cloth/cloth_estimate.hpp>

namespace kit {

double deepest_penetration(const ClothScene& scene, const NodeArray& x) {
  double deepest = 0;
  if (scene.ground) deepest = std::max(deepest, scene.ground->height - x.col(1).minCoeff());
  for (const SphereCollider& sphere : scene.spheres) {
    const double radius = contact_radius(scene.grid, sphere);  // the sphere as the cloth meets it
    for (Eigen::Index i = 0; i < x.rows(); ++i)
      deepest = std::max(deepest, radius - (x.row(i).transpose() - sphere.center).norm());
  }
  return deepest;
}

ClothRecording run_cloth(const ClothScene& scene, const Springs& springs, ClothKernels kernels,
                         const ClothRunOptions& options) {
  ClothScene run_scene = scene;
  if (!options.strain_limit) run_scene.strain_limit.reset();
  ClothSystem cloth(run_scene, springs, kernels);
  const Stopwatch clock;
  ClothRecording rec;
  // The step count is rounded to the nearest whole number of steps; samples and frames fall at
  // the step nearest their time.
  const long steps = std::max(1L, std::lround(options.t_end / options.dt));
  // Sample s of `count` falls at the step nearest s·t_end/count; when there are more samples
  // than steps, a step takes the samples that fall on it once.
  struct Schedule {
    long count, steps, next = 1;
    bool due(long k) {
      bool hit = false;
      while (next <= count && std::lround(double(next) * double(steps) / double(count)) <= k)
        ++next, hit = true;
      return hit;
    }
  };
  Schedule samples{options.samples, steps}, frames{options.frames, steps};
  rec.samples.push_back({0, cloth.kinetic(), cloth.potential(), cloth.max_strain()});
  rec.peak_strain = rec.samples.back().strain;
  if (options.frames > 0) rec.frames.push_back(cloth.x), rec.frame_contacts.push_back(0);
  const ProgressWeight weight(options.implicit ? 1 : stages(options.integrator));  // an RK4 step: 4 passes
  ProgressCounter progress;
  std::unique_ptr<ImplicitStepper> implicit;
  if (options.implicit)
    implicit =
        make_implicit_stepper(cloth, *options.implicit, options.implicit_settings, options.implicit_kernels);
  for (long k = 1; k <= steps; ++k) {
    try {
      if (implicit)
        implicit->step(cloth, options.dt);
      else
        cloth.step(options.integrator, options.dt);
    } catch (const SolveFailed& e) {
      rec.exploded_at = cloth.t + options.dt;  // the step that could not be taken
      rec.failure = e.what();
      break;
    }
    ++rec.steps;
    progress.add(1);
    const bool sample_due = samples.due(k), frame_due = frames.due(k);
    // The strain is measured (over every structural spring) every 8 steps, and before anything is
    // recorded: often enough to stop a run that grows by orders of magnitude, and to record no
    // exploded state, at a few percent of a step's cost.
    if (k % 8 != 0 && k != steps && !sample_due && !frame_due) continue;
    const double strain = cloth.blew_up() ? INFINITY : cloth.max_strain();
    rec.peak_strain = std::max(rec.peak_strain, strain);
    if (strain > exploded_strain) {
      rec.exploded_at = cloth.t;
      // The energy it reached, when it is still a number: the table shows how far it went.
      if (!cloth.blew_up()) rec.samples.push_back({cloth.t, cloth.kinetic(), cloth.potential(), strain});
      break;
    }
    rec.deepest = std::max(rec.deepest, deepest_penetration(run_scene, cloth.x));
    if (sample_due) rec.samples.push_back({cloth.t, cloth.kinetic(), cloth.potential(), strain});
    if (frame_due) {
      rec.frames.push_back(cloth.x);
      rec.frame_contacts.push_back(cloth.work.contacts + (implicit ? implicit->work.filtered_nodes : 0));
    }
  }
  rec.work = cloth.work;
  if (implicit) rec.implicit = implicit->work;
  rec.wall_seconds = clock.seconds();
  return rec;
}

ClothRuns run_each_integrator(const ClothScene& scene, const Springs& springs, ClothKernels kernels,
                              const ClothRunOptions& options) {
  ClothRuns runs;
  // The section's progress line counts force evaluations per spring pass: these four runs and
  // compare_strain_limit's one after them (estimate_cloth_chapter's work).
  ProgressTask::set_total(estimate_cloth_chapter(scene, options).work);
  for (ClothIntegrator integrator : all_cloth_integrators) {
    ClothRunOptions one = options;
    one.integrator = integrator;
    if (integrator != options.integrator) one.frames = 0;
    runs[integrator] = run_cloth(scene, springs, kernels, one);
  }
  return runs;
}

StrainComparison compare_strain_limit(const ClothScene& scene, const Springs& springs, ClothKernels kernels,
                                      ClothRunOptions options, const ClothRecording& as_run) {
  ClothScene limited = scene;
  if (!limited.strain_limit) limited.strain_limit = StrainLimit{};
  options.frames = 0;
  options.strain_limit = !scene.strain_limit;  // the run the scene did not ask for
  ClothRecording other = run_cloth(limited, springs, kernels, options);
  StrainComparison c;
  c.max_strain = limited.strain_limit->max_strain;
  ClothRecording kept = as_run;  // the scene's run without its frames: the comparison needs none
  kept.frames.clear();
  c.free = scene.strain_limit ? std::move(other) : std::move(kept);
  c.limited = scene.strain_limit ? std::move(kept) : std::move(other);
  return c;
}

}  // namespace kit
