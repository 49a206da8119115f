// A cloth run as a pane of a 3D page (cloth_page.hpp).
#include "cloth_page.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include <kit/cloth/cloth_stability.hpp>

namespace kit {

std::vector<double> cloth_page_times(const ClothRunOptions& run) {
  std::vector<double> times;
  for (int k = 0; k <= run.frames; ++k) times.push_back(k * run.t_end / std::max(run.frames, 1));
  return times;
}

WebPage cloth_page(const std::string& title, const ClothScene& scene, const ClothRunOptions& run,
                   std::vector<PagePane> panes) {
  WebPage page;
  page.title = title;
  page.subtitle = scene.description;
  page.fps = run.frames > 0 ? run.frames / run.t_end : 30;
  page.times = cloth_page_times(run);
  page.panes = std::move(panes);
  return page;
}

std::string cloth_run_label(const ClothRunOptions& run) {
  return fmt::format("{}, Δt = {:.3g} s",
                     run.implicit ? display_name(*run.implicit) : display_name(run.integrator), run.dt);
}

PageWritten write_cloth_page(ChapterApp& app, const std::string& chapter, const ClothScene& scene,
                             const ClothRecording& rec, const ClothRunOptions& run,
                             const std::filesystem::path& out_dir) {
  return write_page(app,
                    cloth_page(chapter + ": '" + scene.name + "'", scene, run,
                               {cloth_pane(scene, rec, run, cloth_run_label(run))}),
                    out_dir / "cloth.html");
}

PageWritten write_stability_page(ChapterApp& app, const ClothScene& scene, ClothKernels kernels,
                                 const ClothRunOptions& run, const std::filesystem::path& out_dir) {
  if (app.options().no_viewer || app.options().no_plot) return {};  // and no runs either
  // The prediction 2/ω_max is for undamped springs (cloth_stability.hpp): the scene's springs
  // without their damping, and without the strain limit, which would hold a growing mode back.
  ClothScene undamped = scene;
  for (auto* family : {&undamped.springs.structural, &undamped.springs.shear, &undamped.springs.bend})
    if (*family) (*family)->damping = 0;
  const Springs bare = kernels.build_springs(undamped.grid, undamped.springs);
  const ClothSystem cloth(undamped, bare, kernels);
  const double limit = predicted_dt_max(ClothIntegrator::symplectic_euler,
                                        omega_max(bare, cloth.masses(), cloth.x, cloth.pins()).omega);  // [s]
  std::vector<PagePane> panes;
  for (const double factor : {0.9, 1.1}) {
    ClothRunOptions near = run;
    near.integrator = ClothIntegrator::symplectic_euler, near.implicit.reset();
    near.dt = factor * limit, near.strain_limit = false;
    const ClothRecording rec = run_cloth(undamped, bare, kernels, near);
    panes.push_back(
        cloth_pane(undamped, rec, near,
                   fmt::format("symplectic Euler, Δt = {:g} × 2/ω_max = {:.3g} s", factor, near.dt)));
  }
  WebPage page =
      cloth_page(fmt::format("Chapter 6: '{}' just below and just above its stable step", scene.name), scene,
                 run, std::move(panes));
  page.subtitle = fmt::format("its springs undamped, no strain limit; 2/ω_max = {:.4g} s", limit);
  return write_page(app, page, out_dir / "cloth-stability.html");
}

PagePane cloth_pane(const ClothScene& scene, const ClothRecording& rec, const ClothRunOptions& run,
                    const std::string& label) {
  const double seconds = rec.wall_seconds;
  PagePane pane;
  pane.label = label;
  if (seconds > 0 && rec.steps > 0) {
    const double simulated = rec.exploded_at >= 0 ? rec.exploded_at : run.t_end;  // [s]
    pane.cost =
        fmt::format("{:.3g} s of computing per simulated second", seconds / std::max(simulated, 1e-9));
  }
  if (rec.exploded_at >= 0)
    pane.ended =
        fmt::format("{} at t = {:.4g} s", rec.failure.empty() ? "exploded" : "stopped", rec.exploded_at);
  pane.facts = {{"sheet", fmt::format("{} × {} nodes", scene.grid.nx, scene.grid.ny)},
                {"step", fmt::format("{:.4g} s", run.dt)},
                {"steps taken", fmt::format("{}", rec.steps)}};
  PageMesh mesh;
  mesh.name = "cloth";
  const ClothGrid& grid = scene.grid;
  for (int j = 0; j + 1 < grid.ny; ++j)  // the OBJ writer's triangles (obj_mesh.cpp)
    for (int i = 0; i + 1 < grid.nx; ++i) {
      const auto a = std::uint32_t(grid.index(i, j)), b = a + 1, c = a + std::uint32_t(grid.nx) + 1,
                 d = a + std::uint32_t(grid.nx);
      mesh.triangles.push_back({a, b, c}), mesh.triangles.push_back({a, c, d});
    }
  for (const Pin& pin : scene.pins) mesh.pins.push_back(int(pinned_node(grid, pin)));
  const std::vector<double> times = cloth_page_times(run);
  PageReadout energy{"energy E", "J", {}}, change{"E − E(0)", "J", {}}, strain{"largest stretch", "%", {}, 3};
  for (std::size_t k = 0; k < rec.frames.size(); ++k) {
    const NodeArray& x = rec.frames[k];
    std::vector<Vec3> frame(std::size_t(x.rows()));
    for (long n = 0; n < x.rows(); ++n) frame[std::size_t(n)] = x.row(n).transpose();
    mesh.frames.push_back(std::move(frame));
    // The sample nearest the frame's time (samples fall at steps, frames at k·t_end/frames).
    const auto nearest = std::min_element(
        rec.samples.begin(), rec.samples.end(),
        [&](const auto& a, const auto& b) { return std::abs(a.t - times[k]) < std::abs(b.t - times[k]); });
    const bool close = nearest != rec.samples.end() &&
                       std::abs(nearest->t - times[k]) <= 0.5 * run.t_end / std::max(run.samples, 1) + run.dt;
    energy.values.push_back(close ? nearest->total() : NAN);
    change.values.push_back(close ? nearest->total() - rec.samples.front().total() : NAN);
    strain.values.push_back(close ? 100 * nearest->strain : NAN);
  }
  pane.readouts = {energy, change, strain};
  if (!scene.spheres.empty() || scene.ground) {  // the contacts made since the frame before
    PageReadout contacts{"contacts since the last frame", "", {}, 6};
    for (std::size_t k = 0; k < rec.frame_contacts.size(); ++k)
      contacts.values.push_back(double(rec.frame_contacts[k] - (k > 0 ? rec.frame_contacts[k - 1] : 0)));
    pane.readouts.push_back(contacts);
  }
  pane.meshes.push_back(std::move(mesh));
  for (const SphereCollider& s : scene.spheres) pane.spheres.push_back({"collider", s.center, s.radius});
  if (scene.ground) pane.ground = PageGround{scene.ground->height, 4 * std::max(grid.width, grid.height)};
  return pane;
}

}  // namespace kit
