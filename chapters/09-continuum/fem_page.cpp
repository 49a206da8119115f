// Chapter 9's scene as a 3D page (fem_page.hpp).
#include "fem_page.hpp"

#include <fmt/format.h>

#include <kit/base/stopwatch.hpp>

#include "continuum_experiments.hpp"
#include "fem_output.hpp"

namespace kit {

void PlatePage::add(const FemBody& body, double t) {
  const TriangleMesh& mesh = body.mesh();
  if (mesh_.triangles.empty()) {
    mesh_.name = "plate";
    mesh_.color = "#6a8caf";
    mesh_.scalar_name = "Green strain |E|";
    for (const auto& t3 : mesh.triangles)
      mesh_.triangles.push_back({std::uint32_t(t3[0]), std::uint32_t(t3[1]), std::uint32_t(t3[2])});
  }
  std::vector<Vec3> positions(std::size_t(body.nodes()));
  for (long k = 0; k < body.nodes(); ++k) positions[std::size_t(k)] = body.x.row(k).transpose();
  // Each node's strain: the mean of its triangles' |E| (E = ½(FᵀF − I), ex 9.1).
  std::vector<double> sum(positions.size(), 0.0), count(positions.size(), 0.0);
  double largest = 0;
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    const double strain = body.kernels().element.green_strain(body.gradient(e)).norm();
    largest = std::max(largest, strain);
    for (const int node : mesh.triangles[e]) sum[std::size_t(node)] += strain, count[std::size_t(node)] += 1;
  }
  for (std::size_t k = 0; k < sum.size(); ++k) sum[k] /= std::max(count[k], 1.0);
  double kinetic = 0;  // ½ Σ m |v|² [J]
  for (long k = 0; k < body.nodes(); ++k) kinetic += 0.5 * body.masses[k] * body.v.row(k).squaredNorm();
  mesh_.frames.push_back(std::move(positions));
  mesh_.scalar.push_back(std::move(sum));
  times_.push_back(t);
  strain_.values.push_back(largest);
  elastic_.values.push_back(body.elastic_energy());
  kinetic_.values.push_back(kinetic);
}

PageWritten PlatePage::write(ChapterApp& app, const std::filesystem::path& path, const std::string& ended,
                             double seconds, double simulated) const {
  if (times_.empty()) return {};
  WebPage page;
  page.title = "Chapter 9: the spinning plate";
  page.subtitle = "free, spun about its centre: its strain is what keeps it together";
  page.times = times_;
  page.fps = times_.size() > 1 ? double(times_.size() - 1) / (times_.back() - times_.front()) : 30;
  PagePane pane;
  pane.label = label_;
  pane.ended = ended;
  if (simulated > 0)
    pane.cost = fmt::format("{:.3g} s of computing per simulated second", seconds / simulated);
  pane.readouts = {strain_, elastic_, kinetic_};
  pane.meshes = {mesh_};
  page.panes = {pane};
  return write_page(app, page, path);
}

void plate_scene(ChapterApp& app, const ContinuumSetup& s, const ContinuumKernels& kernels) {
  if (app.options().no_plot || s.frames == 0) return;
  const auto dir = std::filesystem::path(app.options().out_dir) / "plate_meshes";
  std::filesystem::create_directories(dir);
  PlatePage page(fmt::format("{}, {}", model_name(s.model), time_integrator_names.display(s.integrator)));
  const auto write = [&](const FemBody& body, int frame, double t) {
    write_fem_obj(dir / fmt::format("plate-{:04d}.obj", frame), body);
    if (!app.options().no_viewer) page.add(body, t);
  };
  const Stopwatch clock;
  const auto run = spin_plate(s.material, s.model, s.integrator, s.resolution, s.mesh, s.dt, s.t_end, kernels,
                              int(s.frames) - 1, write);
  app.report().say(
      "scene", "\n6. {frames} OBJ meshes of the {model} plate in {dir}.\n",
      {{"frames", long(run.samples.size())}, {"model", model_name(s.model)}, {"dir", dir.string()}});
  const auto ended = run.diverged ? fmt::format("diverged at t = {:.4g} s", run.diverged_at) : std::string();
  page.write(app, dir.parent_path() / "plate.html", ended, clock.seconds(),
             run.diverged ? run.diverged_at : s.t_end);
}

}  // namespace kit
