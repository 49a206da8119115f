#include <kit/cloth/cloth_scene_file.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include <kit/base/usage.hpp>

#include "../app/toml_read.hpp"

namespace kit {
namespace {

using scene_toml::kind;
using scene_toml::Reader;
using scene_toml::Section;
using scene_toml::symmetric;
using scene_toml::to_vec3;

// Bounds beyond which a value is a typo, not a scene (metres, seconds, kilograms).
constexpr double max_coordinate = 1e6;   // [m]
constexpr double max_sheet_side = 1000;  // [m]
constexpr int max_nodes_per_side = 4096;
constexpr double max_stiffness = 1e9;      // [N/m]
constexpr double max_damping = 1e6;        // [N·s/m]
constexpr double max_friction = 10;        // Coulomb μ
constexpr double max_acceleration = 1000;  // [m/s²]
// Below this |v − (v·u)u|/|v|, v is too close to u for the grid to span an area.
constexpr double parallel_tolerance = 1e-6;

/// A direction: three numbers, not all zero.
Vec3 direction(const Section& s, std::string_view k, const Vec3& fallback) {
  const auto a = s.vec3(k, symmetric(max_coordinate));
  if (!a) return fallback;
  const Vec3 d = to_vec3(*a);
  if (!(d.norm() > 0)) s.reader().bad(*s.find(k), s.key(k), "must not be zero: it is a direction");
  return d;
}

/// Two values of an [a, b] pair, each read by `element(node, key)`.
template <class T, class Read>
std::optional<std::array<T, 2>> pair(const Section& s, std::string_view k, std::string_view elements,
                                     std::string_view components, Read element) {
  const auto* n = s.find(k);
  if (!n) return std::nullopt;
  const toml::array& a = s.reader().array(*n, s.key(k), 2, elements, components);
  return std::array<T, 2>{element(*a.get(0), fmt::format("{}[0]", s.key(k))),
                          element(*a.get(1), fmt::format("{}[1]", s.key(k)))};
}

void read_grid(const Section& s, ClothGrid& grid) {
  s.only({"nodes", "size", "origin", "u", "v", "density"});
  const Reader& r = s.reader();
  const auto nodes = pair<long>(
      s, "nodes", "integers", "nx, ny",
      [&](const toml::node& n, const std::string& key) { return r.integer(n, key, 2, max_nodes_per_side); });
  if (!nodes) s.missing("nodes", "the grid's node counts [nx, ny], each in [2, 4096]");
  const auto size = pair<double>(
      s, "size", "numbers", "width, height",
      [&](const toml::node& n, const std::string& key) { return r.real(n, key, positive(max_sheet_side)); });
  if (!size) s.missing("size", "the sheet's [width, height] [m]");
  grid.nx = int((*nodes)[0]);
  grid.ny = int((*nodes)[1]);
  grid.width = (*size)[0];
  grid.height = (*size)[1];
  if (const auto origin = s.vec3("origin", symmetric(max_coordinate))) grid.origin = to_vec3(*origin);

  // u and v as given may be any lengths and need not be orthogonal: the grid's rest shape is
  // rectangular, so v keeps only its part orthogonal to u (Gram–Schmidt).
  const Vec3 u = direction(s, "u", grid.u).normalized();
  const Vec3 v_given = direction(s, "v", grid.v);
  const Vec3 v = v_given - v_given.dot(u) * u;
  if (!(v.norm() > parallel_tolerance * v_given.norm())) {
    const std::string why = fmt::format(
        "must not be parallel to u = [{}, {}, {}]: the sheet would have no area", u.x(), u.y(), u.z());
    if (const auto* n = s.find("v")) r.bad(*n, s.key("v"), why);
    r.fail_at(s.table().source(), fmt::format("{} (the default [0, 0, 1]) {}", s.key("v"), why));
  }
  grid.u = u;
  grid.v = v.normalized();
  grid.areal_density = s.real("density", positive(1000)).value_or(grid.areal_density);
}

SpringFamily read_family(const Section& s, bool is_bend, BendLayout& layout) {
  if (is_bend)
    s.only({"stiffness", "damping", "layout"});
  else
    s.only({"stiffness", "damping"});
  SpringFamily family;
  const auto stiffness = s.real("stiffness", positive(max_stiffness));
  if (!stiffness) s.missing("stiffness", "a spring family needs its stiffness K [N/m] in (0, 1e9]");
  family.stiffness = *stiffness;
  family.damping = s.real("damping", between(0, max_damping)).value_or(0);
  if (const auto* n = s.find("layout")) {
    const auto* count = n->as_integer();
    if (!count || (count->get() != 4 && count->get() != 8))
      s.reader().bad(
          *n, s.key("layout"),
          "must be 4 (two steps along the axes, Provot) or 8 (also the two-step diagonals; ERRATA 12)");
    layout = count->get() == 4 ? BendLayout::four : BendLayout::eight;
  }
  return family;
}

void read_springs(const Section& s, SpringLayout& springs) {
  s.only({"structural", "shear", "bend"});
  if (const auto t = s.sub("structural"))
    springs.structural = read_family(*t, false, springs.bend_layout);
  else
    s.missing("structural", "a cloth needs its structural springs ([springs.structural] stiffness = ..)");
  if (const auto t = s.sub("shear")) springs.shear = read_family(*t, false, springs.bend_layout);
  if (const auto t = s.sub("bend")) springs.bend = read_family(*t, true, springs.bend_layout);
}

void read_pins(const Reader& r, const toml::node& n, const ClothGrid& grid, std::vector<Pin>& pins) {
  const auto* list = n.as_array();
  if (!list) r.bad(n, "pins", fmt::format("expected an array of [i, j] pairs, got {}", kind(n)));
  for (std::size_t p = 0; p < list->size(); ++p) {
    const std::string key = fmt::format("pins[{}]", p);
    const toml::node& item = *list->get(p);
    const toml::array& ij = r.array(item, key, 2, "integers", "i, j");
    // Within the grid, counting from either end: [−nx, nx − 1] and [−ny, ny − 1].
    const long i = r.integer(*ij.get(0), key + "[0]", -grid.nx, grid.nx - 1);
    const long j = r.integer(*ij.get(1), key + "[1]", -grid.ny, grid.ny - 1);
    pins.push_back({int(i), int(j)});
  }
}

SphereCollider read_sphere(const Section& s) {
  s.only({"center", "radius", "friction"});
  SphereCollider sphere;
  const auto center = s.vec3("center", symmetric(max_coordinate));
  if (!center) s.missing("center", "a sphere needs its center [x, y, z] [m]");
  sphere.center = to_vec3(*center);
  const auto radius = s.real("radius", positive(max_coordinate));
  if (!radius) s.missing("radius", "a sphere needs its radius [m] > 0");
  sphere.radius = *radius;
  sphere.friction = s.real("friction", between(0, max_friction)).value_or(0);
  return sphere;
}

void read_spheres(const Reader& r, const toml::node& n, std::vector<SphereCollider>& spheres) {
  const auto* list = n.as_array();
  if (!list || !list->is_array_of_tables())
    r.bad(n, "sphere", fmt::format("expected an array of tables ([[sphere]]), got {}", kind(n)));
  for (std::size_t i = 0; i < list->size(); ++i)
    spheres.push_back(read_sphere(Section(r, *list->get(i)->as_table(), fmt::format("sphere[{}]", i))));
}

void read_camera(const Section& s, Camera& camera) {
  s.only({"position", "target", "fov_deg"});
  if (const auto p = s.vec3("position", symmetric(max_coordinate))) camera.position = to_vec3(*p);
  if (const auto t = s.vec3("target", symmetric(max_coordinate))) camera.target = to_vec3(*t);
  camera.fov_deg = s.real("fov_deg", RealRange{0, 180, true, true}).value_or(camera.fov_deg);
  if (camera.position == camera.target) {
    const std::string what = "must differ from camera.position: the camera looks from position to target";
    if (const auto* n = s.find("target")) s.reader().bad(*n, s.key("target"), what);
    s.reader().fail_at(s.table().source(), s.key("target") + " " + what);
  }
}

void read_run(const Section& s, ClothScene& scene) {
  s.only({"integrator", "dt", "t_end", "frames"});
  scene.integrator = s.choice("integrator", cloth_integrator_names).value_or(scene.integrator);
  scene.dt = s.real("dt", positive(1)).value_or(scene.dt);
  scene.t_end = s.real("t_end", positive(1e4)).value_or(scene.t_end);
  scene.frames = int(s.integer("frames", 1, 20'000).value_or(scene.frames));
}

}  // namespace

ClothScene parse_cloth_scene(std::string_view text, std::string_view file_name) {
  const Reader r{std::string(file_name)};
  const toml::table document = r.parse(text);
  const Section root(r, document, "");
  root.only({"name", "description", "pins", "cloth", "springs", "forces", "sphere", "ground", "strain_limit",
             "camera", "run"});

  ClothScene scene;
  const auto name = root.string("name");
  if (!name) root.missing("name", "a scene has a name");
  if (name->empty()) r.bad(*root.find("name"), "name", "must not be empty");
  scene.name = *name;
  scene.description = root.string("description").value_or("");

  const auto cloth = root.sub("cloth");
  if (!cloth) root.missing("cloth", "a scene needs its sheet: [cloth] nodes = [nx, ny], size = [w, h] [m]");
  read_grid(*cloth, scene.grid);
  const auto springs = root.sub("springs");
  if (!springs) root.missing("springs", "a cloth needs springs: [springs.structural] stiffness = .. [N/m]");
  read_springs(*springs, scene.springs);
  if (const auto* pins = root.find("pins")) read_pins(r, *pins, scene.grid, scene.pins);

  if (const auto forces = root.sub("forces")) {
    forces->only({"gravity", "drag"});
    if (const auto g = forces->vec3("gravity", symmetric(max_acceleration))) scene.gravity = to_vec3(*g);
    scene.drag = forces->real("drag", between(0, 1000));
  }
  if (const auto* spheres = root.find("sphere")) read_spheres(r, *spheres, scene.spheres);
  if (const auto ground = root.sub("ground")) {
    ground->only({"height", "friction"});
    GroundCollider g;
    g.height = ground->real("height", symmetric(max_coordinate)).value_or(g.height);
    g.friction = ground->real("friction", between(0, max_friction)).value_or(g.friction);
    scene.ground = g;
  }
  if (const auto limit = root.sub("strain_limit")) {
    limit->only({"max_strain", "iterations"});
    StrainLimit l;
    l.max_strain = limit->real("max_strain", positive(10)).value_or(l.max_strain);
    l.iterations = int(limit->integer("iterations", 1, 100).value_or(l.iterations));
    scene.strain_limit = l;
  }
  if (const auto camera = root.sub("camera")) read_camera(*camera, scene.camera);
  if (const auto run = root.sub("run")) read_run(*run, scene);
  return scene;
}

ClothScene load_cloth_scene(const std::filesystem::path& file) {
  return parse_cloth_scene(scene_toml::read_text(file), file.string());
}

}  // namespace kit
