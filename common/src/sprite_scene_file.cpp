#include <kit/sprite_scene_file.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include <kit/usage.hpp>

namespace kit {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr long long no_limit = std::numeric_limits<long long>::max();

// Bounds that keep every later product finite in float32 and double: a scene is small (metres,
// seconds), and a value beyond these is a typo, not a scene.
constexpr double max_coordinate = 1e6;  // [m]
constexpr double max_rate_of_change = 1000;  // colour, alpha [1/s], size [m/s], wind [m/s], g [m/s²]

/// An interval of allowed reals; it also says in words what it allows.
struct Range {
  double lo = -inf, hi = inf;
  bool lo_open = false, hi_open = false;

  bool contains(double x) const {
    return std::isfinite(x) && (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
  }
  std::string describe() const {
    if (lo == -inf && hi == inf) return "";
    if (hi == inf) return fmt::format(" {} {}", lo_open ? ">" : ">=", lo);
    if (lo == -inf) return fmt::format(" {} {}", hi_open ? "<" : "<=", hi);
    return fmt::format(" in {}{}, {}{}", lo_open ? '(' : '[', lo, hi, hi_open ? ')' : ']');
  }
};

Range closed(double lo, double hi) { return {lo, hi, false, false}; }
Range above(double lo, double hi) { return {lo, hi, true, false}; }
Range symmetric(double bound) { return closed(-bound, bound); }

/// "a string", "an integer": what a node is, for "expected X, got Y".
std::string_view kind(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    default: return "nothing";
  }
}

/// The value as the scene file would write it, on one line, cut short when long.
std::string show(const toml::node& n) {
  std::string s;
  if (const auto* v = n.as_integer()) {
    s = fmt::format("{}", v->get());
  } else if (const auto* f = n.as_floating_point()) {
    s = fmt::format("{}", f->get());
  } else if (const auto* b = n.as_boolean()) {
    s = b->get() ? "true" : "false";
  } else if (const auto* str = n.as_string()) {
    s = fmt::format("\"{}\"", str->get());
  } else if (const auto* a = n.as_array()) {
    s = "[";
    for (std::size_t i = 0; i < a->size(); ++i) s += (i ? ", " : "") + show(*a->get(i));
    s += "]";
  } else if (const auto* t = n.as_table()) {
    s = "{";
    bool first = true;
    for (const auto& kv : *t) {
      s += fmt::format("{} {} = {}", first ? "" : ",", kv.first.str(), show(kv.second));
      first = false;
    }
    s += " }";
  } else {
    std::ostringstream os;
    n.visit([&os](const auto& x) { os << x; });
    s = os.str();
  }
  constexpr std::size_t longest = 80;
  if (s.size() > longest) s = s.substr(0, longest - 3) + "...";
  return s;
}

std::string join(std::initializer_list<std::string_view> words) {
  std::string s;
  for (auto w : words) s += (s.empty() ? "" : ", ") + std::string(w);
  return s;
}

/// Turns a position in the file into the message's "file:line: " prefix.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail_at(const toml::source_region& where, std::string_view what) const {
    // The root table of a document has no line of its own: its mistakes are on line 1.
    const auto line = std::max<toml::source_index>(where.begin.line, 1);
    throw UsageError(fmt::format("{}:{}: {}", file_, line, what));
  }
  [[noreturn]] void fail(const toml::node& n, std::string_view what) const { fail_at(n.source(), what); }
  [[noreturn]] void bad(const toml::node& n, const std::string& key, std::string_view what) const {
    fail(n, fmt::format("{} = {}: {}", key, show(n), what));
  }

  double real(const toml::node& n, const std::string& key, Range range) const {
    double x = 0;
    if (const auto* f = n.as_floating_point())
      x = f->get();
    else if (const auto* i = n.as_integer())  // TOML's 2 where 2.0 is meant
      x = static_cast<double>(i->get());
    else
      bad(n, key, fmt::format("expected a number, got {}", kind(n)));
    if (!range.contains(x)) bad(n, key, "must be a finite number" + range.describe());
    return x;
  }

  long integer(const toml::node& n, const std::string& key, long long lo, long long hi) const {
    const auto* i = n.as_integer();
    if (!i) bad(n, key, fmt::format("expected an integer, got {}", kind(n)));
    const long long x = i->get();
    if (x < lo || x > hi)
      bad(n, key, hi == no_limit ? fmt::format("must be an integer >= {}", lo)
                                 : fmt::format("must be an integer in [{}, {}]", lo, hi));
    return static_cast<long>(x);
  }

  std::string string(const toml::node& n, const std::string& key) const {
    const auto* s = n.as_string();
    if (!s) bad(n, key, fmt::format("expected a string, got {}", kind(n)));
    return s->get();
  }

  bool boolean(const toml::node& n, const std::string& key) const {
    const auto* b = n.as_boolean();
    if (!b) bad(n, key, fmt::format("expected true or false, got {}", kind(n)));
    return b->get();
  }

  /// Index of the string's value in `names`.
  std::size_t choice(const toml::node& n, const std::string& key, std::initializer_list<std::string_view> names) const {
    const std::string s = string(n, key);
    const auto it = std::find(names.begin(), names.end(), s);
    if (it == names.end()) bad(n, key, "must be one of " + join(names));
    return static_cast<std::size_t>(std::distance(names.begin(), it));
  }

  /// Three numbers, each in `range`; `components` names them for the message ("x, y, z").
  Vec3d vec3(const toml::node& n, const std::string& key, Range range, std::string_view components) const {
    const auto* a = n.as_array();
    if (!a) bad(n, key, fmt::format("expected an array of 3 numbers [{}], got {}", components, kind(n)));
    if (a->size() != 3)
      bad(n, key, fmt::format("expected an array of 3 numbers [{}], got {} elements", components, a->size()));
    Vec3d v{};
    for (std::size_t i = 0; i < 3; ++i) v[i] = real(*a->get(i), fmt::format("{}[{}]", key, i), range);
    return v;
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

/// One TOML table and its dotted key ("emitter[0]", "" for the document).
class Section {
 public:
  Section(const Reader& reader, const toml::table& table, std::string path)
      : r_(reader), table_(table), path_(std::move(path)) {}

  std::string key(std::string_view k) const { return path_.empty() ? std::string(k) : path_ + "." + std::string(k); }
  const toml::node* find(std::string_view k) const { return table_.get(k); }
  const toml::table& table() const { return table_; }

  /// Refuses every key not in `allowed`: a misspelt key would otherwise be silently ignored.
  void only(std::initializer_list<std::string_view> allowed) const {
    for (const auto& kv : table_) {
      const std::string_view k = kv.first.str();
      if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
        r_.fail_at(kv.first.source(), fmt::format("unknown key '{}' (allowed: {})", key(k), join(allowed)));
    }
  }

  [[noreturn]] void missing(std::string_view k, std::string_view why) const {
    r_.fail_at(table_.source(), fmt::format("missing key '{}': {}", key(k), why));
  }

  std::optional<double> real(std::string_view k, Range range) const {
    if (const auto* n = find(k)) return r_.real(*n, key(k), range);
    return std::nullopt;
  }
  std::optional<long> integer(std::string_view k, long long lo, long long hi) const {
    if (const auto* n = find(k)) return r_.integer(*n, key(k), lo, hi);
    return std::nullopt;
  }
  std::optional<std::string> string(std::string_view k) const {
    if (const auto* n = find(k)) return r_.string(*n, key(k));
    return std::nullopt;
  }
  std::optional<bool> boolean(std::string_view k) const {
    if (const auto* n = find(k)) return r_.boolean(*n, key(k));
    return std::nullopt;
  }
  std::optional<std::size_t> choice(std::string_view k, std::initializer_list<std::string_view> names) const {
    if (const auto* n = find(k)) return r_.choice(*n, key(k), names);
    return std::nullopt;
  }
  std::optional<Vec3d> vec3(std::string_view k, Range range, std::string_view components = "x, y, z") const {
    if (const auto* n = find(k)) return r_.vec3(*n, key(k), range, components);
    return std::nullopt;
  }
  std::optional<Vec3d> colour(std::string_view k) const { return vec3(k, closed(0, 1), "r, g, b"); }

  /// The sub-table at `k`, or nullopt when the scene leaves it out.
  std::optional<Section> sub(std::string_view k) const {
    const auto* n = find(k);
    if (!n) return std::nullopt;
    const auto* t = n->as_table();
    if (!t) r_.bad(*n, key(k), fmt::format("expected a table, got {}", kind(*n)));
    return Section(r_, *t, key(k));
  }

  /// A Reeves attribute: a number (variance 0) or { mean, variance }. `mean` bounds the mean; when
  /// `draws` is given, every draw mean ± variance must lie in it too.
  std::optional<Spread> spread(std::string_view k, Range mean, std::optional<Range> draws = std::nullopt,
                               double variance_max = inf) const {
    const auto* n = find(k);
    if (!n) return std::nullopt;
    const std::string name = key(k);
    Spread s;
    if (n->is_number()) {
      s.mean = r_.real(*n, name, mean);
    } else if (const auto* t = n->as_table()) {
      const Section inner(r_, *t, name);
      inner.only({"mean", "variance"});
      const auto m = inner.real("mean", mean);
      if (!m) inner.missing("mean", "{ mean = .., variance = .. } needs its mean");
      s.mean = *m;
      s.variance = inner.real("variance", {0, variance_max, false, false}).value_or(0);
    } else {
      r_.bad(*n, name, fmt::format("expected a number or {{ mean = .., variance = .. }}, got {}", kind(*n)));
    }
    if (draws && !(draws->contains(s.mean - s.variance) && draws->contains(s.mean + s.variance)))
      r_.bad(*n, name, fmt::format("every draw mean ± variance must be a number{}, got [{}, {}]", draws->describe(),
                                   s.mean - s.variance, s.mean + s.variance));
    return s;
  }

 private:
  const Reader& r_;
  const toml::table& table_;
  std::string path_;
};

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
  camera.position = s.vec3("position", symmetric(max_coordinate)).value_or(camera.position);
  camera.target = s.vec3("target", symmetric(max_coordinate)).value_or(camera.target);
  camera.fov_deg = s.real("fov_deg", closed(1, 170)).value_or(camera.fov_deg);
}

void read_forces(const Reader& r, const Section& s, SpriteForces& forces) {
  s.only({"gravity", "drag", "wind"});
  forces.gravity = s.vec3("gravity", symmetric(max_rate_of_change));
  forces.drag = s.real("drag", closed(1e-9, 1000));  // k below 1e-9 1/s: no drag a scene could see
  forces.wind = s.vec3("wind", symmetric(max_rate_of_change));
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
              fmt::format("min must be < max in every component, but {} min = {} >= max = {}", "xyz"[i], (*lo)[i],
                          (*hi)[i]));
    death.region = std::array<Vec3d, 2>{*lo, *hi};
  }
}

bool is_png_path(const std::string& s) {
  if (s.size() <= 4) return false;
  std::string ext = s.substr(s.size() - 4);
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".png";
}

Emitter read_emitter(const Reader& r, const Section& s, EmitterSource& source) {
  s.only({"name", "shape", "position", "axis", "radius", "angle_deg", "rate", "speed", "lifetime", "size", "alpha",
          "colour", "colour_variance", "colour_rate", "alpha_rate", "size_rate", "blend", "texture", "burst_only",
          "on_death", "inherit_velocity", "first_frame", "last_frame"});
  Emitter e;
  const auto name = s.string("name");
  if (!name) s.missing("name", "every emitter has a name (on_death refers to emitters by name)");
  if (name->empty()) r.bad(*s.find("name"), s.key("name"), "must not be empty");
  e.name = *name;

  if (const auto shape = s.choice("shape", {"point", "disc", "sphere", "cone"}))
    e.shape = static_cast<EmitterShape>(*shape);
  e.position = s.vec3("position", symmetric(max_coordinate)).value_or(e.position);
  if (const auto axis = s.vec3("axis", symmetric(max_coordinate))) {
    const double norm = std::hypot((*axis)[0], (*axis)[1], (*axis)[2]);
    if (!(norm > 0)) r.bad(*s.find("axis"), s.key("axis"), "must not be zero: it is a direction");
    for (std::size_t i = 0; i < 3; ++i) e.axis[i] = (*axis)[i] / norm;
  }
  e.radius = s.real("radius", closed(0, max_coordinate)).value_or(e.radius);
  if ((e.shape == EmitterShape::disc || e.shape == EmitterShape::sphere) && !(e.radius > 0)) {
    const char* shape = e.shape == EmitterShape::disc ? "disc" : "sphere";
    const std::string why = fmt::format("a {} emitter needs a radius > 0 [m]", shape);
    if (const auto* n = s.find("radius")) r.bad(*n, s.key("radius"), why);
    s.missing("radius", why);
  }
  e.angle_deg = s.real("angle_deg", closed(0, 180)).value_or(e.angle_deg);

  // A rate's variance may exceed its mean: a negative draw emits no particle that frame.
  constexpr double max_rate = 1e7;  // particles per frame or per burst
  e.rate = s.spread("rate", closed(0, max_rate), std::nullopt, max_rate).value_or(e.rate);
  e.speed = s.spread("speed", closed(0, 1e5), closed(0, 1e5)).value_or(e.speed);
  e.lifetime = s.spread("lifetime", above(0, 1e6), above(0, 1e6)).value_or(e.lifetime);
  e.size = s.spread("size", closed(0, max_coordinate), closed(0, max_coordinate)).value_or(e.size);
  e.alpha = s.spread("alpha", closed(0, 1), closed(0, 1)).value_or(e.alpha);
  e.colour = s.colour("colour").value_or(e.colour);
  e.colour_variance = s.colour("colour_variance").value_or(e.colour_variance);
  e.colour_rate = s.vec3("colour_rate", symmetric(max_rate_of_change), "r, g, b").value_or(e.colour_rate);
  e.alpha_rate = s.real("alpha_rate", symmetric(max_rate_of_change)).value_or(e.alpha_rate);
  e.size_rate = s.real("size_rate", symmetric(max_rate_of_change)).value_or(e.size_rate);
  if (const auto blend = s.choice("blend", {"over", "additive"})) e.blend = static_cast<Blend>(*blend);

  if (const auto texture = s.string("texture")) {
    static constexpr std::array<std::string_view, 4> built_in{"soft", "spark", "flake", "smoke"};
    if (std::find(built_in.begin(), built_in.end(), *texture) != built_in.end()) {
      e.texture = *texture;
    } else if (is_png_path(*texture)) {
      // Relative to the scene, so that a scene and its images move together.
      e.texture = (std::filesystem::path(r.file()).parent_path() / *texture).lexically_normal().string();
    } else {
      r.bad(*s.find("texture"), s.key("texture"), "must be soft, spark, flake, smoke or a path ending in .png");
    }
  }

  e.burst_only = s.boolean("burst_only").value_or(e.burst_only);
  source.burst_only = s.find("burst_only");
  if (const auto target = s.string("on_death")) {
    source.on_death = s.find("on_death");
    source.on_death_name = *target;
  }
  e.inherit_velocity = s.real("inherit_velocity", closed(0, 1)).value_or(e.inherit_velocity);
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
void link_emitters(const Reader& r, std::vector<Emitter>& emitters, const std::vector<EmitterSource>& sources) {
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
      r.bad(*sources[i].on_death, key, "an emitter may not burst itself: each burst's deaths would start another");
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
  if (list && list->empty()) r.bad(*n, "emitter", fmt::format("expected 1 to {} emitters, got 0", max_emitters));
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
  toml::table document;
  try {
    document = toml::parse(text, file_name);
  } catch (const toml::parse_error& e) {
    r.fail_at(e.source(), fmt::format("TOML syntax error at column {}: {}", e.source().begin.column, e.description()));
  }

  const Section root(r, document, "");
  root.only({"name", "frames", "fps", "warmup", "max_particles", "background", "camera", "forces", "death", "emitter"});
  SpriteScene scene;
  scene.file = std::string(file_name);
  const auto name = root.string("name");
  if (!name) root.missing("name", "a scene has a name");
  if (name->empty()) r.bad(*root.find("name"), "name", "must not be empty");
  scene.name = *name;
  scene.frames = root.integer("frames", 1, 20'000).value_or(scene.frames);
  scene.fps = root.real("fps", closed(1, 1000)).value_or(scene.fps);
  scene.warmup = root.real("warmup", closed(0, 600)).value_or(scene.warmup);
  scene.max_particles = root.integer("max_particles", 1, 50'000'000).value_or(scene.max_particles);
  scene.background = root.colour("background").value_or(scene.background);

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
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw UsageError(fmt::format("cannot read scene file {}: {}", file.string(),
                                 std::filesystem::exists(file, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || !text) throw UsageError(fmt::format("cannot read scene file {}: read failed", file.string()));
  return parse_sprite_scene(text.str(), file.string());
}

}  // namespace kit
