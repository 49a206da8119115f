// Chapter 8's scene runs as 3D pages (rigid_page.hpp).
#include "rigid_page.hpp"

#include <algorithm>

#include <fmt/format.h>

#include <kit/base/stopwatch.hpp>
#include <kit/rigid/rigid_mesh.hpp>

#include "rigid_experiments.hpp"

namespace kit {
namespace fs = std::filesystem;

PagePane rigid_pane(const RigidShape& shape, const std::vector<RigidState>& frames, const std::string& label,
                    bool ground) {
  PagePane pane;
  pane.label = label;
  PageMesh mesh;
  mesh.name = shape.name;
  mesh.color = "#3d7cc8";
  mesh.flat = true;
  PageReadout energy{"rotational energy", "J", {}}, momentum{"|L|", "kg·m²/s", {}},
      drift{"‖RᵀR − I‖", "", {}, 3}, height{"centre height", "m", {}};
  for (const RigidState& state : frames) {
    std::vector<Vec3> corners;
    for (const RigidFace& face : rigid_faces(shape, state))
      corners.insert(corners.end(), face.corners.begin(), face.corners.end());
    if (mesh.triangles.empty())  // the faces' corners come 4 by 4, counter-clockwise from outside
      for (std::uint32_t f = 0; 4 * f < corners.size(); ++f)
        mesh.triangles.push_back({4 * f, 4 * f + 1, 4 * f + 2}),
            mesh.triangles.push_back({4 * f, 4 * f + 2, 4 * f + 3});
    mesh.frames.push_back(std::move(corners));
    energy.values.push_back(rotational_energy(shape, state));
    momentum.values.push_back(state.L.norm());
    drift.values.push_back(orthonormality_error(state.R));
    height.values.push_back(state.x.y());
  }
  pane.readouts = {energy, momentum, drift};
  if (ground) pane.readouts.push_back(height), pane.ground = PageGround{0, 4};
  pane.meshes.push_back(std::move(mesh));
  return pane;
}

namespace {

std::vector<double> frame_times(std::size_t count, double seconds) {
  std::vector<double> times;
  for (std::size_t k = 0; k < count; ++k)
    times.push_back(seconds * double(k) / double(std::max<std::size_t>(count, 2) - 1));
  return times;
}

}  // namespace

void write_rigid_pages(ChapterApp& app, const RigidSetup& s, const RigidKernels& kernels,
                       const std::vector<RotationIntegrator>& integrators, const RigidState& start,
                       const DropRun& drop, double drop_seconds) {
  if (app.options().no_plot || app.options().no_viewer || s.frames == 0) return;
  const fs::path out = app.options().out_dir;
  WebPage tumble;
  tumble.title =
      fmt::format("Chapter 8: the {} tumbling, {:g} s at h = {:.3g} s", s.shape.name, s.t_end, s.dt);
  tumble.subtitle = "spun about its intermediate axis: the flips are the Dzhanibekov effect";
  tumble.fps = double(s.frames) / s.t_end;
  tumble.times = frame_times(std::size_t(s.frames) + 1, s.t_end);
  for (const RotationIntegrator i : {RotationIntegrator::euler_matrix, RotationIntegrator::euler_quaternion,
                                     RotationIntegrator::exponential_map, RotationIntegrator::midpoint}) {
    if (std::find(integrators.begin(), integrators.end(), i) == integrators.end()) continue;
    const Stopwatch clock;
    const RotationRun run = run_free_rotation(kernels, i, s.shape, start, s.dt, s.t_end, 2, s.frames);
    const double seconds = clock.seconds();
    PagePane pane = rigid_pane(s.shape, run.frames, display_name(i), false);
    pane.cost = fmt::format("{:.3g} s of computing per simulated second", seconds / s.t_end);
    pane.facts = {{"step", fmt::format("{:.3g} s", s.dt)},
                  {"flips", fmt::format("{}", run.flip_times.size())}};
    if (run.diverged_at >= 0) pane.ended = fmt::format("diverged at t = {:.4g} s", run.diverged_at);
    tumble.panes.push_back(std::move(pane));
  }
  if (!tumble.panes.empty()) write_page(app, tumble, out / (s.shape.name + ".html"));
  WebPage dropped;
  dropped.title =
      fmt::format("Chapter 8: a box dropped tilted, {} at h = {:.3g} s", display_name(s.integrator), s.dt);
  dropped.subtitle = "impulses at its corners against the ground";
  dropped.times = frame_times(drop.frames.size(), drop_seconds);
  dropped.fps = double(std::max<std::size_t>(drop.frames.size(), 2) - 1) / drop_seconds;
  dropped.panes.push_back(rigid_pane(shape_named("box"), drop.frames, display_name(s.integrator), true));
  if (!drop.frames.empty()) write_page(app, dropped, out / "drop.html");
}

}  // namespace kit
