// Sprite scene files (sprite_scene_file.hpp): the shipped scenes load, absent keys keep their
// defaults, and every mistake is a UsageError naming the file, the line and the dotted key.
#include <kit_catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <string_view>

#include <kit/base/usage.hpp>
#include <kit/sprites/sprite_scene_file.hpp>

#include "printed_as.hpp"

namespace {

const std::filesystem::path scene_dir =
    std::filesystem::path(__FILE__).parent_path() / "../../../chapters/05-sprites/scenes";

/// The message of the UsageError that parsing `text` as "scenes/test.toml" throws.
std::string error_of(std::string_view text) {
  try {
    kit::parse_sprite_scene(text, "scenes/test.toml");
  } catch (const kit::UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

constexpr std::string_view one_emitter = R"(name = "t"
[[emitter]]
name = "e"
)";

}  // namespace

TEST_CASE("each shipped scene loads, with at least one emitter", "[sprite-scene]") {
  for (const char* name : {"fountain.toml", "fire-and-smoke.toml", "fireworks.toml", "snow.toml"}) {
    INFO(name);
    const auto scene = kit::load_sprite_scene(scene_dir / name);
    CHECK_FALSE(scene.name.empty());
    CHECK_FALSE(scene.emitters.empty());
    CHECK(scene.file == (scene_dir / name).string());
  }
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scene_dir))
    if (entry.path().extension() == ".toml") {
      INFO(entry.path().string());
      CHECK_NOTHROW(kit::load_sprite_scene(entry.path()));
      ++files;
    }
  CHECK(files >= 4);
}

TEST_CASE("the shipped fireworks: each shell bursts through its own burst_only emitter, found by name",
          "[sprite-scene]") {
  const auto scene = kit::load_sprite_scene(scene_dir / "fireworks.toml");
  REQUIRE(scene.emitters.size() == 6);
  for (int shell = 0; shell < 3; ++shell) {
    const int burst = shell + 3;
    CHECK(scene.emitters[std::size_t(shell)].on_death == burst);
    CHECK_FALSE(scene.emitters[std::size_t(shell)].burst_only);
    CHECK(scene.emitters[std::size_t(burst)].burst_only);
    CHECK_FALSE(scene.emitters[std::size_t(burst)].on_death);
    CHECK(scene.emitters[std::size_t(burst)].inherit_velocity == 0.3);
  }
  CHECK(scene.emitters[0].rate.mean == 0.012);
  // The README: "a rate of 0.012 shells a frame gives a shell every 2.8 s on average", at the
  // scene's frame rate (the mean of the emitted count is the rate itself: test_sprites.cpp).
  CHECK(1 / (scene.emitters[0].rate.mean * scene.fps) == kit::test::printed("2.8"));
  CHECK(scene.forces.gravity.has_value());
  CHECK(scene.death.region.has_value());
}

TEST_CASE("snow falls at a terminal velocity of about 1 m/s", "[sprite-scene]") {
  const auto scene = kit::load_sprite_scene(scene_dir / "snow.toml");
  REQUIRE(scene.forces.gravity);
  REQUIRE(scene.forces.drag);
  CHECK(std::abs((*scene.forces.gravity)[1]) / *scene.forces.drag == Approx(1.0).epsilon(0.1));
  CHECK(scene.forces.wind.has_value());
}

TEST_CASE("a scene without drag has no drag, and forces it does not name stay absent", "[sprite-scene]") {
  const auto scene = kit::parse_sprite_scene(R"(name = "t"
[forces]
gravity = [0, -9.81, 0]
[[emitter]]
name = "e"
)",
                                             "t.toml");
  CHECK(scene.forces.drag == std::nullopt);
  CHECK(scene.forces.wind == std::nullopt);
  REQUIRE(scene.forces.gravity);
  CHECK((*scene.forces.gravity)[1] == -9.81);
  CHECK(scene.death.alpha_below == std::nullopt);
  CHECK(scene.death.region == std::nullopt);
}

TEST_CASE("keys a scene leaves out keep the defaults of sprite_scene.hpp", "[sprite-scene]") {
  const auto scene = kit::parse_sprite_scene(one_emitter, "t.toml");
  const kit::SpriteScene defaults;
  const kit::Emitter e0;
  CHECK(scene.name == "t");
  CHECK(scene.frames == defaults.frames);
  CHECK(scene.fps == defaults.fps);
  CHECK(scene.max_particles == defaults.max_particles);
  CHECK(scene.background == defaults.background);
  CHECK(scene.camera.position == defaults.camera.position);
  CHECK(scene.camera.target == defaults.camera.target);
  CHECK(scene.camera.fov_deg == defaults.camera.fov_deg);
  CHECK_FALSE(scene.forces.gravity);
  CHECK_FALSE(scene.forces.drag);
  CHECK_FALSE(scene.forces.wind);
  REQUIRE(scene.emitters.size() == 1);
  const auto& e = scene.emitters[0];
  CHECK(e.name == "e");
  CHECK(e.shape == e0.shape);
  CHECK(e.axis == e0.axis);
  CHECK(e.lifetime.mean == e0.lifetime.mean);
  CHECK(e.size.mean == e0.size.mean);
  CHECK(e.alpha.mean == e0.alpha.mean);
  CHECK(e.blend == e0.blend);
  CHECK(e.texture == e0.texture);
  CHECK_FALSE(e.burst_only);
  CHECK_FALSE(e.on_death);
  CHECK_FALSE(e.last_frame);
}

TEST_CASE("a spread is a number (variance 0) or { mean, variance }; integers are numbers", "[sprite-scene]") {
  const auto scene = kit::parse_sprite_scene(R"(name = "t"
fps = 24
[[emitter]]
name = "e"
rate = 5
speed = { mean = 3, variance = 0.5 }
lifetime = { mean = 2 }
axis = [0, 0, 2]
)",
                                             "t.toml");
  CHECK(scene.fps == 24.0);
  const auto& e = scene.emitters[0];
  CHECK(e.rate.mean == 5.0);
  CHECK(e.rate.variance == 0.0);
  CHECK(e.speed.mean == 3.0);
  CHECK(e.speed.variance == 0.5);
  CHECK(e.lifetime.variance == 0.0);
  CHECK(e.axis == kit::Vec3{0, 0, 1});  // normalised
}

TEST_CASE("a rate's variance may exceed its mean: negative draws emit nothing", "[sprite-scene]") {
  const auto scene = kit::parse_sprite_scene(R"(name = "t"
[[emitter]]
name = "e"
rate = { mean = 0.04, variance = 0.5 }
)",
                                             "t.toml");
  CHECK(scene.emitters[0].rate.variance == 0.5);
}

TEST_CASE("a PNG texture is resolved against the scene file's folder; built-in names stay",
          "[sprite-scene]") {
  const auto scene = kit::parse_sprite_scene(R"(name = "t"
[[emitter]]
name = "a"
texture = "images/drop.png"
[[emitter]]
name = "b"
texture = "spark"
)",
                                             "scenes/x.toml");
  CHECK(std::filesystem::path(scene.emitters[0].texture) == std::filesystem::path("scenes/images/drop.png"));
  CHECK(scene.emitters[1].texture == "spark");
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "a"
texture = "sprak"
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("emitter[0].texture") &&
                 ContainsSubstring(".png"));
}

TEST_CASE("an unknown key names the file, its line, the key and the allowed keys", "[sprite-scene]") {
  CHECK_THAT(error_of(R"(name = "t"
frames = 10

emiter = 3
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("unknown key 'emiter'") &&
                 ContainsSubstring("allowed: name, frames"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
speed = { mean = 1, varience = 2 }
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("emitter[0].speed.varience") &&
                 ContainsSubstring("mean, variance"));
  CHECK_THAT(error_of(R"(name = "t"
[camera]
fov = 30
[[emitter]]
name = "e"
)"),
             ContainsSubstring("scenes/test.toml:3:") && ContainsSubstring("camera.fov'"));
}

TEST_CASE("a value of the wrong type names the file, its line, the key and both types", "[sprite-scene]") {
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
rate = { mean = "fast" }
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("emitter[0].rate.mean") &&
                 ContainsSubstring("expected a number, got a string"));
  CHECK_THAT(error_of(R"(name = "t"
frames = 12.5
[[emitter]]
name = "e"
)"),
             ContainsSubstring("scenes/test.toml:2:") && ContainsSubstring("frames = 12.5") &&
                 ContainsSubstring("expected an integer"));
  CHECK_THAT(error_of(R"(name = "t"
background = [0, 0]
[[emitter]]
name = "e"
)"),
             ContainsSubstring("scenes/test.toml:2:") && ContainsSubstring("background") &&
                 ContainsSubstring("3 numbers"));
  CHECK_THAT(error_of(R"(name = "t"
[emitter]
name = "e"
)"),
             ContainsSubstring("scenes/test.toml:2:") && ContainsSubstring("emitter") &&
                 ContainsSubstring("[[emitter]]"));
}

TEST_CASE("an out-of-range value names the file, its line, the key, the value and the range",
          "[sprite-scene]") {
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
shape = "cone"
speed = { mean = 1, variance = -1 }
)"),
             ContainsSubstring("scenes/test.toml:5:") &&
                 ContainsSubstring("emitter[0].speed.variance = -1: must be a finite number >= 0"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
[[emitter]]
name = "f"
colour = [1, 2, 0.5]
)"),
             ContainsSubstring("scenes/test.toml:6:") && ContainsSubstring("emitter[1].colour[1] = 2") &&
                 ContainsSubstring("in [0, 1]"));
  CHECK_THAT(error_of(R"(name = "t"
fps = nan
[[emitter]]
name = "e"
)"),
             ContainsSubstring("scenes/test.toml:2:") && ContainsSubstring("fps = nan") &&
                 ContainsSubstring("finite"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
lifetime = { mean = 1, variance = 1 }
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("emitter[0].lifetime") &&
                 ContainsSubstring("(0, 1000000]"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
alpha = { mean = 0.8, variance = 0.3 }
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("emitter[0].alpha") &&
                 ContainsSubstring("[0, 1]"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
first_frame = 10
last_frame = 3
)"),
             ContainsSubstring("scenes/test.toml:5:") && ContainsSubstring("emitter[0].last_frame = 3") &&
                 ContainsSubstring("first_frame (10)"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
axis = [0, 0, 0]
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("emitter[0].axis") &&
                 ContainsSubstring("zero"));
  CHECK_THAT(error_of(R"(name = "t"
[death]
region = { min = [0, 0, 0], max = [1, 0, 1] }
[[emitter]]
name = "e"
)"),
             ContainsSubstring("scenes/test.toml:3:") && ContainsSubstring("death.region") &&
                 ContainsSubstring("min must be < max"));
}

TEST_CASE("a scene has 1 to 255 emitters", "[sprite-scene]") {
  CHECK_THAT(error_of("name = \"t\"\nemitter = []\n"), ContainsSubstring("scenes/test.toml:2:") &&
                                                           ContainsSubstring("emitter = []") &&
                                                           ContainsSubstring("got 0"));
  std::string many = "name = \"t\"\n";
  for (int i = 0; i < 256; ++i) many += "[[emitter]]\nname = \"e" + std::to_string(i) + "\"\n";
  CHECK_THAT(error_of(many), ContainsSubstring("scenes/test.toml:2:") && ContainsSubstring("1 to 255") &&
                                 ContainsSubstring("got 256"));
  many.resize(many.rfind("[[emitter]]"));
  CHECK(kit::parse_sprite_scene(many, "t.toml").emitters.size() == 255);
}

TEST_CASE("a disc or sphere emitter without a positive radius is refused", "[sprite-scene]") {
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
shape = "disc"
)"),
             ContainsSubstring("scenes/test.toml:2:") && ContainsSubstring("emitter[0].radius") &&
                 ContainsSubstring("disc"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
shape = "sphere"
radius = 0
)"),
             ContainsSubstring("scenes/test.toml:5:") && ContainsSubstring("emitter[0].radius = 0") &&
                 ContainsSubstring("sphere"));
}

TEST_CASE("on_death naming no emitter, itself, or a loop is refused at its line", "[sprite-scene]") {
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "shell"
on_death = "bust"
[[emitter]]
name = "burst"
burst_only = true
)"),
             ContainsSubstring("scenes/test.toml:4:") &&
                 ContainsSubstring("emitter[0].on_death = \"bust\"") && ContainsSubstring("shell, burst"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "shell"
on_death = "shell"
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("emitter[0].on_death") &&
                 ContainsSubstring("itself"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "a"
on_death = "b"
[[emitter]]
name = "b"
on_death = "a"
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("emitter[0].on_death") &&
                 ContainsSubstring("a -> b -> a"));
}

TEST_CASE("a burst_only emitter that no on_death names never emits and is refused", "[sprite-scene]") {
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "shell"
[[emitter]]
name = "burst"
burst_only = true
)"),
             ContainsSubstring("scenes/test.toml:6:") && ContainsSubstring("emitter[1].burst_only") &&
                 ContainsSubstring("never emits"));
}

TEST_CASE("two emitters with one name are refused: on_death could not tell them apart", "[sprite-scene]") {
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
[[emitter]]
name = "e"
)"),
             ContainsSubstring("scenes/test.toml:5:") && ContainsSubstring("emitter[1].name") &&
                 ContainsSubstring("unique"));
}

TEST_CASE("wind without drag is refused: it acts through drag", "[sprite-scene]") {
  CHECK_THAT(error_of(R"(name = "t"
[forces]
gravity = [0, -9.81, 0]
wind = [1, 0, 0]
[[emitter]]
name = "e"
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("forces.wind") &&
                 ContainsSubstring("drag"));
}

TEST_CASE("a TOML syntax error names the file and its line", "[sprite-scene]") {
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
name = "e"
rate = { mean = 3,
)"),
             ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("TOML syntax error"));
}

TEST_CASE("a missing required key is reported at the line of its table", "[sprite-scene]") {
  CHECK_THAT(error_of(R"(frames = 3
[[emitter]]
name = "e"
)"),
             ContainsSubstring("scenes/test.toml:1:") && ContainsSubstring("missing key 'name'"));
  CHECK_THAT(error_of(R"(name = "t"
[[emitter]]
rate = 3
)"),
             ContainsSubstring("scenes/test.toml:2:") && ContainsSubstring("missing key 'emitter[0].name'"));
  CHECK_THAT(error_of(R"(name = "t"
)"),
             ContainsSubstring("scenes/test.toml:1:") && ContainsSubstring("missing key 'emitter'"));
  CHECK_THAT(
      error_of(R"(name = "t"
[[emitter]]
name = "e"
size = { variance = 1 }
)"),
      ContainsSubstring("scenes/test.toml:4:") && ContainsSubstring("missing key 'emitter[0].size.mean'"));
}

TEST_CASE("a scene file that cannot be read is a UsageError naming it", "[sprite-scene]") {
  std::string message = "(no error)";
  try {
    kit::load_sprite_scene(scene_dir / "no-such-scene.toml");
  } catch (const kit::UsageError& e) {
    message = e.what();
  }
  CHECK_THAT(message, ContainsSubstring("cannot read scene file") && ContainsSubstring("no-such-scene.toml"));
  CHECK_THROWS_AS(kit::load_sprite_scene(scene_dir), kit::UsageError);
}
