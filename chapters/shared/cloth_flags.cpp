#include "cloth_flags.hpp"

#include <algorithm>
#include <system_error>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>

#include <kit/app/scene_flag.hpp>
#include <kit/base/usage.hpp>
#include <kit/cloth/cloth_scene_file.hpp>

namespace kit {
namespace {

ClothIntegrator integrator_named(const std::string& name) {
  if (const auto integrator = cloth_integrator_names.parse(name)) return *integrator;
  throw UsageError(fmt::format("--integrator: '{}' is not one of {}", name,
                               fmt::join(cloth_integrator_names.flags(), ", ")));
}

nlohmann::json vector_json(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

}  // namespace

void add_cloth_flags(ChapterApp& app, ClothFlags& f, const std::vector<std::string>& more_integrators) {
  app.add_viewer_flag();
  app.cli()
      .add_option("--scene", f.scene,
                  "scene: a name under chapters/06-cloth-explicit/scenes/ or a .toml path")
      ->type_name("NAME|FILE")
      ->capture_default_str();
  std::vector<std::string> names = cloth_integrator_names.flags();
  names.insert(names.end(), more_integrators.begin(), more_integrators.end());
  const std::string default_one = more_integrators.empty() ? "the scene's" : more_integrators.front();
  app.add_choice("--integrator", f.integrator,
                 fmt::format("{} (default: {})", fmt::join(names, ", "), default_one), names);
  app.add_real("--dt", f.dt, "time step Δt [s] (default: the scene's)", positive(1));
  app.add_real("--t-end", f.t_end, "simulated duration [s] (default: the scene's)", positive(1e4));
  app.add_count("--resolution", f.resolution,
                "nodes across the sheet; rows follow so that cells stay near square (default: the scene's)",
                2, 100'000);
  app.add_count("--frames", f.frames, "frames written over [0, t_end] (default: the scene's)", 1, 20'000);
  app.add_count("--width", f.width, "frame width [px]", 16, 4096);
  app.add_count("--height", f.height, "frame height [px]", 16, 4096);
}

ClothScene load_cloth_scene_flag(const ClothFlags& flags, const std::filesystem::path& scenes_dir) {
  return load_cloth_scene(scene_file(flags.scene, scenes_dir));
}

ClothScene apply_cloth_flags(ClothScene scene, const ClothFlags& flags) {
  if (!flags.integrator.empty()) scene.integrator = integrator_named(flags.integrator);
  if (flags.dt > 0) scene.dt = flags.dt;
  if (flags.t_end > 0) scene.t_end = flags.t_end;
  if (flags.frames > 0) scene.frames = int(flags.frames);
  if (flags.resolution > 0) {
    try {
      scene = at_resolution(scene, int(flags.resolution));
    } catch (const UsageError& e) {
      throw UsageError(fmt::format("--resolution: {}", e.what()));
    }
  }
  return scene;
}

nlohmann::json cloth_scene_summary(const ClothScene& s) {
  using nlohmann::json;
  const ClothGrid& g = s.grid;
  json springs = json::object();
  for (SpringKind kind : all_spring_kinds) {
    const auto& family = s.springs.family(kind);
    springs[spring_kind_name(kind)] =
        family ? json{{"stiffness", family->stiffness}, {"damping", family->damping}} : json(nullptr);
  }
  springs["bend_layout"] = s.springs.bend_layout == BendLayout::four ? 4 : 8;
  json pins = json::array();
  for (const Pin& p : s.pins) pins.push_back({p.i, p.j});
  json spheres = json::array();
  for (const SphereCollider& c : s.spheres)
    spheres.push_back({{"center", vector_json(c.center)}, {"radius", c.radius}, {"friction", c.friction}});
  return {
      {"name", s.name},
      {"description", s.description},
      {"grid",
       {{"nx", g.nx},
        {"ny", g.ny},
        {"nodes", g.nodes()},
        {"width", g.width},
        {"height", g.height},
        {"origin", vector_json(g.origin)},
        {"u", vector_json(g.u)},
        {"v", vector_json(g.v)},
        {"areal_density", g.areal_density}}},
      {"springs", springs},
      {"gravity", s.gravity ? vector_json(*s.gravity) : json(nullptr)},
      {"drag", s.drag ? json(*s.drag) : json(nullptr)},
      {"pins", pins},
      {"spheres", spheres},
      {"ground",
       s.ground ? json{{"height", s.ground->height}, {"friction", s.ground->friction}} : json(nullptr)},
      {"strain_limit", s.strain_limit ? json{{"max_strain", s.strain_limit->max_strain},
                                             {"iterations", s.strain_limit->iterations}}
                                      : json(nullptr)},
      {"camera",
       {{"position", vector_json(s.camera.position)},
        {"target", vector_json(s.camera.target)},
        {"fov_deg", s.camera.fov_deg}}},
      {"integrator", flag_name(s.integrator)},
      {"dt", s.dt},
      {"t_end", s.t_end},
      {"frames", s.frames},
  };
}

ClothRunOptions cloth_run_options(const ClothScene& scene) {
  ClothRunOptions run;
  run.integrator = scene.integrator;
  run.dt = scene.dt;
  run.t_end = scene.t_end;
  run.frames = scene.frames;
  return run;
}

std::string describe_cloth_flags(const ClothScene& scene) {
  return fmt::format("--resolution {} ({}×{} nodes), --dt {} s, --t-end {} s, --frames {}", scene.grid.nx,
                     scene.grid.nx, scene.grid.ny, scene.dt, scene.t_end, scene.frames);
}

}  // namespace kit
