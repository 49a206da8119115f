#include <kit/sprites/sprite_scene_file.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include <kit/base/usage.hpp>

#include "../app/toml_read.hpp"

namespace kit {
namespace {

using scene_toml::kind;
using scene_toml::no_limit;
using scene_toml::Reader;
using scene_toml::Section;
using scene_toml::symmetric;
using scene_toml::to_vec3;

constexpr double inf = std::numeric_limits<double>::infinity();

// Bounds that keep every later product finite in float32 and double: a scene is small (metres,
// seconds), and a value beyond these is a typo, not a scene.
constexpr double max_coordinate = 1e6;       // [m]
constexpr double max_rate_of_change = 1000;  // colour, alpha [1/s], size [m/s], wind [m/s], g [m/s²]

/// A Reeves attribute: a number (variance 0) or { mean, variance }. `mean` bounds the mean; when
/// `draws` is given, every draw mean ± variance must lie in it too.
std::optional<Spread> spread(const Section& s, std::string_view k, const RealRange& mean,
                             std::optional<RealRange> draws = std::nullopt, double variance_max = inf) {
  const Reader& r = s.reader();
  const auto* n = s.find(k);
  if (!n) return std::nullopt;
  const std::string name = s.key(k);
  Spread result;
  if (n->is_number()) {
    result.mean = r.real(*n, name, mean);
  } else if (const auto* t = n->as_table()) {
    const Section inner(r, *t, name);
    inner.only({"mean", "variance"});
    const auto m = inner.real("mean", mean);
    if (!m) inner.missing("mean", "{ mean = .., variance = .. } needs its mean");
    result.mean = *m;
    result.variance = inner.real("variance", between(0, variance_max)).value_or(0);
  } else {
    r.bad(*n, name, fmt::format("expected a number or {{ mean = .., variance = .. }}, got {}", kind(*n)));
  }
  const double low = result.mean - result.variance, high = result.mean + result.variance;
  if (draws && !(draws->contains(low) && draws->contains(high)))
    r.bad(*n, name,
          fmt::format("every draw mean ± variance must be {}, got [{}, {}]", draws->describe(), low, high));
  return result;
}

std::optional<Colour> colour(const Section& s, std::string_view k) {
  return s.vec3(k, between(0, 1), "r, g, b");
}

constexpr std::size_t max_emitters = 255;  // a particle stores its emitter's index in a byte

/// What the checks across emitters need to point back at.
struct EmitterSource {
  const toml::table* table = nullptr;
  const toml::node* on_death = nullptr;    // the on_death value, when given
  const toml::node* burst_only = nullptr;  // the burst_only value, when given
  std::string on_death_name;
};

void read_camera(const Section& s, Camera& camera) {
  s.only({"position", "target", "fov_deg"});
  if (const auto p = s.vec3("position", symmetric(max_coordinate))) camera.position = to_vec3(*p);
  if (const auto t = s.vec3("target", symmetric(max_coordinate))) camera.target = to_vec3(*t);
  camera.fov_deg = s.real("fov_deg", between(1, 170)).value_or(camera.fov_deg);
}

void read_forces(const Reader& r, const Section& s, SpriteForces& forces) {
  s.only({"gravity", "drag", "wind"});
  if (const auto g = s.vec3("gravity", symmetric(max_rate_of_change))) forces.gravity = to_vec3(*g);
  forces.drag = s.real("drag", between(1e-9, 1000));  // k below 1e-9 1/s: no drag a scene could see
  if (const auto w = s.vec3("wind", symmetric(max_rate_of_change))) forces.wind = to_vec3(*w);
  if (forces.wind && !forces.drag)
    r.bad(*s.find("wind"), s.key("wind"),
          "wind acts through drag (a = -k (v - wind)), so it needs forces.drag > 0 [1/s]");
}

void read_death(const Reader& r, const Section& s, DeathRules& death) {
  s.only({"alpha_below", "region"});
  death.alpha_below = s.real("alpha_below", {0, 1, false, true});
  if (const auto region = s.sub("region")) {
    region->only({"min", "max"});
    const auto lo = region->vec3("min", symmetric(max_coordinate));
    if (!lo) region->missing("min", "a region is a box { min = [x, y, z], max = [x, y, z] } [m]");
    const auto hi = region->vec3("max", symmetric(max_coordinate));
    if (!hi) region->missing("max", "a region is a box { min = [x, y, z], max = [x, y, z] } [m]");
    for (std::size_t i = 0; i < 3; ++i)
      if (!((*lo)[i] < (*hi)[i]))
        r.bad(*s.find("region"), s.key("region"),
              fmt::format("min must be < max in every component, but {} min = {} >= max = {}", "xyz"[i],
                          (*lo)[i], (*hi)[i]));
    death.region = std::array<Vec3, 2>{to_vec3(*lo), to_vec3(*hi)};
  }
}

bool is_png_path(const std::string& s) {
  if (s.size() <= 4) return false;
  std::string ext = s.substr(s.size() - 4);
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

Emitter read_emitter(const Reader& r, const Section& s, EmitterSource& source) {
  s.only(
      {"name",        "shape",     "position", "axis",    "radius",     "angle_deg",       "rate",
       "speed",       "lifetime",  "size",     "alpha",   "colour",     "colour_variance", "colour_rate",
       "alpha_rate",  "size_rate", "blend",    "texture", "burst_only", "on_death",        "inherit_velocity",
       "first_frame", "last_frame"});
  Emitter e;
  const auto name = s.string("name");
  if (!name) s.missing("name", "every emitter has a name (on_death refers to emitters by name)");
  if (name->empty()) r.bad(*s.find("name"), s.key("name"), "must not be empty");
  e.name = *name;

  e.shape = s.choice("shape", emitter_shape_names).value_or(e.shape);
  if (const auto p = s.vec3("position", symmetric(max_coordinate))) e.position = to_vec3(*p);
  if (const auto axis = s.vec3("axis", symmetric(max_coordinate))) {
    const double norm = std::hypot((*axis)[0], (*axis)[1], (*axis)[2]);
    if (!(norm > 0)) r.bad(*s.find("axis"), s.key("axis"), "must not be zero: it is a direction");
    for (std::size_t i = 0; i < 3; ++i) e.axis[i] = (*axis)[i] / norm;
  }
  e.radius = s.real("radius", between(0, max_coordinate)).value_or(e.radius);
  if ((e.shape == EmitterShape::disc || e.shape == EmitterShape::sphere) && !(e.radius > 0)) {
    const std::string why =
        fmt::format("a {} emitter needs a radius > 0 [m]", emitter_shape_names.flag(e.shape));
    if (const auto* n = s.find("radius")) r.bad(*n, s.key("radius"), why);
    s.missing("radius", why);
  }
  e.angle_deg = s.real("angle_deg", between(0, 180)).value_or(e.angle_deg);

  // A rate's variance may exceed its mean: a negative draw emits no particle that frame.
  constexpr double max_rate = 1e7;  // particles per frame or per burst
  e.rate = spread(s, "rate", between(0, max_rate), std::nullopt, max_rate).value_or(e.rate);
  e.speed = spread(s, "speed", between(0, 1e5), between(0, 1e5)).value_or(e.speed);
  e.lifetime = spread(s, "lifetime", positive(1e6), positive(1e6)).value_or(e.lifetime);
  e.size = spread(s, "size", between(0, max_coordinate), between(0, max_coordinate)).value_or(e.size);
  e.alpha = spread(s, "alpha", between(0, 1), between(0, 1)).value_or(e.alpha);
  e.colour = colour(s, "colour").value_or(e.colour);
  e.colour_variance = colour(s, "colour_variance").value_or(e.colour_variance);
  e.colour_rate = s.vec3("colour_rate", symmetric(max_rate_of_change), "r, g, b").value_or(e.colour_rate);
  e.alpha_rate = s.real("alpha_rate", symmetric(max_rate_of_change)).value_or(e.alpha_rate);
  e.size_rate = s.real("size_rate", symmetric(max_rate_of_change)).value_or(e.size_rate);
  e.blend = s.choice("blend", blend_names).value_or(e.blend);

  if (const auto texture = s.string("texture")) {
    static constexpr std::array<std::string_view, 4> built_in{"soft", "spark", "flake", "smoke"};
    if (std::find(built_in.begin(), built_in.end(), *texture) != built_in.end()) {
      e.texture = *texture;
    } else if (is_png_path(*texture)) {
      // Relative to the scene, so that a scene and its images move together.
      e.texture = (std::filesystem::path(r.file()).parent_path() / *texture).lexically_normal().string();
    } else {
      r.bad(*s.find("texture"), s.key("texture"),
            "must be soft, spark, flake, smoke or a path ending in .png");
    }
  }

  e.burst_only = s.boolean("burst_only").value_or(e.burst_only);
  source.burst_only = s.find("burst_only");
  if (const auto target = s.string("on_death")) {
    source.on_death = s.find("on_death");
    source.on_death_name = *target;
  }
  e.inherit_velocity = s.real("inherit_velocity", between(0, 1)).value_or(e.inherit_velocity);
  e.first_frame = s.integer("first_frame", 0, no_limit).value_or(e.first_frame);
  if (const auto* n = s.find("last_frame")) {
    e.last_frame = r.integer(*n, s.key("last_frame"), 0, no_limit);
    if (*e.last_frame < e.first_frame)
      r.bad(*n, s.key("last_frame"), fmt::format("must be an integer >= first_frame ({})", e.first_frame));
  }
  source.table = &s.table();
  return e;
}

/// Resolves on_death names to indices and checks what no single emitter can: no emitter bursts
/// itself, directly or through others (each burst's deaths would start the next: the count grows
/// without end), and every burst_only emitter is some emitter's on_death (else it never emits).
void link_emitters(const Reader& r, std::vector<Emitter>& emitters,
                   const std::vector<EmitterSource>& sources) {
  const auto index_of = [&](const std::string& name) -> std::optional<int> {
    for (std::size_t j = 0; j < emitters.size(); ++j)
      if (emitters[j].name == name) return static_cast<int>(j);
    return std::nullopt;
  };
  std::string names;
  for (const auto& e : emitters) names += (names.empty() ? "" : ", ") + e.name;

  for (std::size_t i = 0; i < emitters.size(); ++i) {
    if (!sources[i].on_death) continue;
    const std::string key = fmt::format("emitter[{}].on_death", i);
    const auto j = index_of(sources[i].on_death_name);
    if (!j) r.bad(*sources[i].on_death, key, fmt::format("no emitter has that name (emitters: {})", names));
    if (static_cast<std::size_t>(*j) == i)
      r.bad(*sources[i].on_death, key,
            "an emitter may not burst itself: each burst's deaths would start another");
    emitters[i].on_death = *j;
  }
  for (std::size_t i = 0; i < emitters.size(); ++i) {
    // Each emitter has at most one on_death, so following them from i either ends or comes back.
    std::string chain = emitters[i].name;
    auto j = emitters[i].on_death;
    for (std::size_t steps = 0; j && steps < emitters.size(); ++steps) {
      chain += " -> " + emitters[static_cast<std::size_t>(*j)].name;
      if (static_cast<std::size_t>(*j) == i)
        r.bad(*sources[i].on_death, fmt::format("emitter[{}].on_death", i),
              fmt::format("bursts form a loop ({}): each burst's deaths would start another", chain));
      j = emitters[static_cast<std::size_t>(*j)].on_death;
    }
  }
  for (std::size_t i = 0; i < emitters.size(); ++i) {
    if (!emitters[i].burst_only) continue;
    const bool target = std::any_of(emitters.begin(), emitters.end(), [&](const Emitter& e) {
      return e.on_death && static_cast<std::size_t>(*e.on_death) == i;
    });
    if (!target)
      r.bad(*sources[i].burst_only, fmt::format("emitter[{}].burst_only", i),
            fmt::format("emitter '{}' never emits: no emitter has on_death = \"{}\"", emitters[i].name,
                        emitters[i].name));
  }
}

void read_emitters(const Reader& r, const Section& root, SpriteScene& scene) {
  const auto* n = root.find("emitter");
  if (!n) root.missing("emitter", "a scene needs at least one [[emitter]]");
  const auto* list = n->as_array();
  if (list && list->empty())
    r.bad(*n, "emitter", fmt::format("expected 1 to {} emitters, got 0", max_emitters));
  if (!list || !list->is_array_of_tables())
    r.bad(*n, "emitter", fmt::format("expected an array of tables ([[emitter]]), got {}", kind(*n)));
  if (list->size() > max_emitters)
    r.bad(*n, "emitter", fmt::format("expected 1 to {} emitters, got {}", max_emitters, list->size()));

  std::vector<EmitterSource> sources(list->size());
  for (std::size_t i = 0; i < list->size(); ++i) {
    const Section s(r, *list->get(i)->as_table(), fmt::format("emitter[{}]", i));
    Emitter e = read_emitter(r, s, sources[i]);
    for (std::size_t j = 0; j < scene.emitters.size(); ++j)
      if (scene.emitters[j].name == e.name)
        r.bad(*s.find("name"), s.key("name"),
              fmt::format("emitter[{}] has that name already; on_death needs names to be unique", j));
    scene.emitters.push_back(std::move(e));
  }
  link_emitters(r, scene.emitters, sources);
}

}  // namespace

SpriteScene parse_sprite_scene(std::string_view text, std::string_view file_name) {
  const Reader r{std::string(file_name)};
  const toml::table document = r.parse(text);

  const Section root(r, document, "");
  root.only({"name", "frames", "fps", "warmup", "max_particles", "background", "camera", "forces", "death",
             "emitter"});
  SpriteScene scene;
  scene.file = std::string(file_name);
  const auto name = root.string("name");
  if (!name) root.missing("name", "a scene has a name");
  if (name->empty()) r.bad(*root.find("name"), "name", "must not be empty");
  scene.name = *name;
  scene.frames = root.integer("frames", 1, 20'000).value_or(scene.frames);
  scene.fps = root.real("fps", between(1, 1000)).value_or(scene.fps);
  scene.warmup = root.real("warmup", between(0, 600)).value_or(scene.warmup);
  scene.max_particles = root.integer("max_particles", 1, max_particles_bound).value_or(scene.max_particles);
  scene.background = colour(root, "background").value_or(scene.background);

  if (const auto camera = root.sub("camera")) {
    read_camera(*camera, scene.camera);
    if (scene.camera.position == scene.camera.target) {
      const auto* n = camera->find("target");
      const std::string what = "must differ from camera.position: the camera looks from position to target";
      if (n) r.bad(*n, "camera.target", what);
      r.fail_at(camera->table().source(), "camera.target " + what);
    }
  }
  if (const auto forces = root.sub("forces")) read_forces(r, *forces, scene.forces);
  if (const auto death = root.sub("death")) read_death(r, *death, scene.death);
  read_emitters(r, root, scene);
  return scene;
}

SpriteScene load_sprite_scene(const std::filesystem::path& file) {
  return parse_sprite_scene(scene_toml::read_text(file), file.string());
}

}  // namespace kit
