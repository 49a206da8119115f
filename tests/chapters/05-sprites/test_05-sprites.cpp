// Chapter 5 end to end: the integrators against the closed form of gravity plus drag (recomputed
// here independently), counts, work done only for what a scene lists, reproducible frames, bad
// flags and bad scene files, refusals, divergence, and the animation without ffmpeg. Then the
// particle system with the reference exercises: lifetimes to the frame, conservation, seeds.
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <kit_catch.hpp>
#include <nlohmann/json.hpp>

#include <kit/app/run_estimate.hpp>
#include <kit/sprites/sprite_scene_file.hpp>
#include <kit/sprites/sprite_system.hpp>

#include "chapter_run.hpp"
#include "printed_as.hpp"
#include "process.hpp"
#include "sprite_kernels.hpp"

using nlohmann::json;
namespace fs = std::filesystem;

namespace {
const std::string binary = KIT_CHAPTER_BINARY;

json run_chapter(const std::vector<std::string>& args, const fs::path& out) {
  return kit::test::run_chapter_into(binary, args, out);
}
json run_chapter(const std::vector<std::string>& args) {
  return kit::test::run_chapter_json(binary, args, "ch05");
}
using kit::test::slurp;
fs::path write_scene(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

// The fountain's mean particle, recomputed here: x(t) = x0 + v∞ t + (v0 − v∞)(1 − e^{−kt})/k per
// axis with v∞ = g/k (no wind), and explicit Euler as a student writes it first.
struct Fountain {
  double k = 0.1, g = -9.81, y0 = 0.05, v0 = 6.0, t = 2.5;
  double exact_y(double time) const {
    const double v_inf = g / k;
    return y0 + v_inf * time + (v0 - v_inf) * (1 - std::exp(-k * time)) / k;
  }
  double euler_y(double dt) const {
    double y = y0, v = v0;
    for (long n = std::lround(t / dt), i = 0; i < n; ++i) {
      y += dt * v;
      v += dt * (g - k * v);
    }
    return y;
  }
  double symplectic_y(double dt) const {  // v first, then y with the new v
    double y = y0, v = v0;
    for (long n = std::lround(t / dt), i = 0; i < n; ++i) {
      v += dt * (g - k * v);
      y += dt * v;
    }
    return y;
  }
  double midpoint_y(double dt) const {  // the slope at the half step, from Euler's half step
    double y = y0, v = v0;
    for (long n = std::lround(t / dt), i = 0; i < n; ++i) {
      const double v_half = v + 0.5 * dt * (g - k * v);
      y += dt * v_half;
      v += dt * (g - k * v_half);
    }
    return y;
  }
};
// Rows of the screen for height y on the fountain's axis, with the scene's camera (eye (0, 1.4,
// 4.6) looking at (0, 1, 0), 45° vertical field, 360 rows): a pinhole, recomputed here.
double screen_row(double y) {
  const double ex = 0, ey = 1.4, ez = 4.6, fx = 0 - ex, fy = 1.0 - ey, fz = 0 - ez;
  const double fn = std::sqrt(fx * fx + fy * fy + fz * fz);
  const double f[3] = {fx / fn, fy / fn, fz / fn};
  const double d[3] = {0 - ex, y - ey, 0 - ez};
  const double depth = d[0] * f[0] + d[1] * f[1] + d[2] * f[2];
  // up = the world's y made orthogonal to the view direction
  double up[3] = {-f[1] * f[0], 1 - f[1] * f[1], -f[1] * f[2]};
  const double un = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
  const double focal = 180.0 / std::tan(22.5 * M_PI / 180);
  return 180.0 - focal / depth * (d[0] * up[0] + d[1] * up[1] + d[2] * up[2]) / un;
}
}  // namespace

TEST_CASE("chapter 5: the trade table as the README prints it, each integrator recomputed from its formula") {
  using kit::test::printed;
  const json s = run_chapter({"--frames", "5"});
  const json& rows = s["integrators"];
  // The mean particle goes straight up, so each error is all in y, and on screen it is the
  // distance between two rows. Each method is recomputed here as a student writes it.
  const Fountain f;
  const double exact = f.exact_y(f.t);
  const std::map<std::string, double> y = {{"euler", f.euler_y(1.0 / 30)},
                                           {"symplectic", f.symplectic_y(1.0 / 30)},
                                           {"midpoint", f.midpoint_y(1.0 / 30)}};
  for (const auto& [name, at_fps] : y) {
    INFO(name);
    CHECK(double(rows[name]["error_at_fps"]) == Approx(std::abs(at_fps - exact)).epsilon(1e-9));
    CHECK(double(rows[name]["pixels_at_fps"]) ==
          Approx(std::abs(screen_row(at_fps) - screen_row(exact))).epsilon(1e-6));
  }
  // The README's table, at the digits it prints.
  CHECK(double(rows["euler"]["fitted_order"]) == printed("1.002"));
  CHECK(double(rows["euler"]["error_at_fps"]) == printed("0.34"));
  CHECK(double(rows["euler"]["pixels_at_fps"]) == printed("19"));
  CHECK(double(rows["symplectic"]["fitted_order"]) == printed("1.002"));
  CHECK(double(rows["symplectic"]["error_at_fps"]) == printed("0.43"));
  CHECK(double(rows["symplectic"]["pixels_at_fps"]) == printed("24"));
  CHECK(double(rows["midpoint"]["fitted_order"]) == printed("2.002"));
  CHECK(double(rows["midpoint"]["error_at_fps"]) == printed("3.8e-4"));
  CHECK(double(rows["midpoint"]["pixels_at_fps"]) == printed("0.02"));
  // The closed form: round-off, which the README prints as measured on one machine and the
  // test bounds (another libm's exp gives another last bit).
  CHECK(double(rows["exact"]["error_at_fps"]) < 1e-12);
  CHECK(double(rows["exact"]["pixels_at_fps"]) < 1e-10);
}

TEST_CASE(
    "chapter 5: ex 5.1's draws have the scene's means and half-widths (uniform: half-width = sqrt(3 var))") {
  const json rows = run_chapter({"--frames", "1"})["emission"];
  REQUIRE(rows.size() == 4);
  for (const json& row : rows) {
    INFO(row.dump());
    CHECK(double(row["drawn_mean"]) == Approx(double(row["mean"])).epsilon(0.01));
    CHECK(double(row["drawn_half_width"]) == Approx(double(row["variance"])).epsilon(0.03));
  }
  CHECK(rows[0]["attribute"] == "speed [m/s]");
  CHECK(rows[0]["mean"] == 6.0);
}

TEST_CASE("chapter 5: alive = emitted − dead, and a full store refuses emissions and counts them") {
  const json s = run_chapter({"--frames", "90"});
  const json& c = s["counts"];
  CHECK(long(c["alive"]) == long(c["emitted"]) - long(c["dead"]));
  CHECK(long(c["dead"]) > 0);
  CHECK(long(c["dropped"]) == 0);
  const json small = run_chapter({"--frames", "90", "--max-particles", "500"});
  CHECK(long(small["counts"]["dropped"]) > 0);
  CHECK(long(small["counts"]["peak"]) <= 500);
  CHECK(long(small["counts"]["alive"]) == long(small["counts"]["emitted"]) - long(small["counts"]["dead"]));
}

TEST_CASE("chapter 5: a scene does the work of what it lists, and nothing else") {
  const json fountain = run_chapter({"--frames", "20"})["work"];
  CHECK(long(fountain["steps"]) > 0);
  CHECK(fountain["drag"] == fountain["steps"]);
  CHECK(fountain["region_checks"] == fountain["steps"]);
  CHECK(long(fountain["colour"]) + long(fountain["alpha"]) + long(fountain["size"]) +
            long(fountain["alpha_checks"]) ==
        0);
  const json fire = run_chapter({"--scene", "fire-and-smoke", "--frames", "20"})["work"];
  CHECK(fire["gravity"] == 0);  // buoyancy comes from the wind, through drag
  CHECK(fire["region_checks"] == 0);
  CHECK(fire["alpha_checks"] == fire["steps"]);
  CHECK(fire["colour"] == fire["steps"]);
}

TEST_CASE("chapter 5: the same seed writes byte-identical frames and data; another seed does not") {
  kit::test::TempDir a("ch05-a"), b("ch05-b"), c("ch05-c");
  const std::vector<std::string> args{"--frames", "12", "--width", "96", "--height", "54", "--format", "png"};
  auto with_seed = [&](const std::string& seed) {
    auto v = args;
    v.insert(v.end(), {"--seed", seed});
    return v;
  };
  run_chapter(with_seed("7"), a.path());
  run_chapter(with_seed("7"), b.path());
  run_chapter(with_seed("8"), c.path());
  for (const std::string file : {"frames/frame_0011.png", "counts.dat", "paths.dat", "contact_sheet.png"}) {
    INFO(file);
    REQUIRE(fs::exists(a.path() / file));
    CHECK(slurp(a.path() / file) == slurp(b.path() / file));
    CHECK(slurp(a.path() / file) != slurp(c.path() / file));
  }
  CHECK(fs::exists(a.path() / "play.gp"));
}

TEST_CASE(
    "chapter 5: bad flags and bad scene files are usage errors that name the flag or file, line and key") {
  kit::test::TempDir dir("ch05-scenes");
  const std::string good = slurp(fs::path(KIT_CHAPTER_SOURCE_DIR) / "scenes" / "fountain.toml");
  const auto unknown =
      write_scene(dir.path(), "unknown.toml", "name = 'x'\nframez = 3\n[[emitter]]\nname = 'a'\n");
  const auto wrong_type =
      write_scene(dir.path(), "type.toml", "name = 'x'\n[[emitter]]\nname = 'a'\nrate = 'many'\n");
  const auto range =
      write_scene(dir.path(), "range.toml", "name = 'x'\n[forces]\ndrag = -1\n[[emitter]]\nname = 'a'\n");
  const auto syntax = write_scene(dir.path(), "syntax.toml", "name = 'x\n");
  kit::test::expect_usage_errors(binary,
                                 {
                                     {{"--frames", "0"}, "--frames"},
                                     {{"--fps", "0.5"}, "--fps"},
                                     {{"--integrator", "rk4"}, "--integrator"},
                                     {{"--width", "8"}, "--width"},
                                     {{"--max-particles", "0"}, "--max-particles"},
                                     {{"--seed", "-1"}, "--seed"},
                                     {{"--scene", "volcano"}, "fountain"},  // names the scenes there are
                                     {{"--scene", (dir.path() / "missing.toml").string()}, "missing.toml"},
                                     {{"--scene", unknown.string()}, "unknown.toml:2"},
                                     {{"--scene", unknown.string()}, "framez"},
                                     {{"--scene", wrong_type.string()}, "type.toml:4"},
                                     {{"--scene", wrong_type.string()}, "emitter[0].rate"},
                                     {{"--scene", range.string()}, "range.toml:3"},
                                     {{"--scene", range.string()}, "forces.drag"},
                                     {{"--scene", syntax.string()}, "syntax.toml:1"},
                                 });
  CHECK_FALSE(good.empty());
}

TEST_CASE("chapter 5: a run too long for the machine is refused up front with its estimate") {
  kit::test::TempDir out("ch05-huge");
  const auto result =
      kit::test::run_process(binary, {"--frames", "20000", "--fps", "1000", "--width", "7680", "--height",
                                      "4320", "--out", (out.path() / "figures").string()});
  INFO(result.err);
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, ContainsSubstring("--frames 20000") && ContainsSubstring("takes about"));
  CHECK_FALSE(fs::exists(out.path() / "figures"));
}

TEST_CASE("chapter 5: a billion particles are refused up front with the memory they would need") {
  // 1e9 particles need about 125 GB, 1e11 12 TB, and 1e8 12.5 GB; under KIT_MEMORY_LIMIT = 4 GB
  // each is refused on every machine, however large. The particle store alone is the lower bound.
  const auto run = [](const std::vector<std::string>& env, double count, const fs::path& out) {
    std::vector<std::string> args = env;
    args.insert(args.end(), {binary, "--max-particles", fmt::format("{:g}", count), "--frames", "1", "--out",
                             out.string()});
    return kit::test::run_process("env", args);
  };
  for (const auto& [count, digits] :
       {std::pair{1e8, "100000000"}, std::pair{1e9, "1000000000"}, std::pair{1e11, "100000000000"}}) {
    const double store = count * double(kit::Particles::bytes_per_particle);  // the particle arrays alone
    kit::test::TempDir out("ch05-billion");
    const auto result = run({"KIT_MEMORY_LIMIT=4e9"}, count, out.path() / "figures");
    INFO(result.err);
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.err, ContainsSubstring(std::string("--max-particles ") + digits) &&
                               ContainsSubstring("ask for less memory"));
    std::smatch memory;
    REQUIRE(std::regex_search(result.err, memory, std::regex(R"(and ([0-9.]+) (GB|TB), over the limit)")));
    CHECK(std::stod(memory[1]) * (memory[2] == "TB" ? 1e12 : 1e9) >= store);
    if (count == 1e9) CHECK(memory.str(1) + " " + memory.str(2) == "125 GB");  // the README's figure
    CHECK_FALSE(fs::exists(out.path() / "figures"));
  }
  // A malformed limit is a usage error that names the variable, before anything is written.
  for (const char* bad : {"KIT_MEMORY_LIMIT=lots", "KIT_MEMORY_LIMIT=-1", "KIT_MEMORY_LIMIT=1e3"}) {
    kit::test::TempDir out("ch05-limit");
    const auto result = run({bad}, 1000, out.path() / "figures");
    INFO(bad << ": " << result.err);
    CHECK(result.exit_code == 2);
    CHECK_THAT(result.err, ContainsSubstring("KIT_MEMORY_LIMIT"));
    CHECK_FALSE(fs::exists(out.path() / "figures"));
  }
}

TEST_CASE("chapter 5: explicit Euler past Δt = 2/k diverges: a reported result, exit 3 only on request") {
  kit::test::TempDir dir("ch05-stiff");
  // |1 − kΔt| = 9 > 1 for k = 10 1/s at 1 fps: every step multiplies the velocity by −9.
  const auto stiff = write_scene(
      dir.path(), "stiff.toml",
      "name = 'stiff'\n[forces]\ndrag = 10\ngravity = [0, -9.81, 0]\n[[emitter]]\nname = 'a'\nrate = 5\n"
      "speed = 5\nlifetime = 1000\n");
  const std::vector<std::string> args{"--scene",  stiff.string(), "--fps",        "1",
                                      "--frames", "400",          "--integrator", "euler"};
  const json s = run_chapter(args);
  REQUIRE(s.contains("divergences"));
  CHECK_THAT(s["divergences"].dump(), ContainsSubstring("infinite at frame"));
  CHECK(long(s["counts"]["frames"]) < 400);
  auto failing = args;
  failing.insert(failing.end(), {"--fail-on-divergence", "--no-plot", "--out", (dir.path() / "o").string()});
  CHECK(kit::test::run_process(binary, failing).exit_code == 3);
  const json exact = run_chapter({"--scene", stiff.string(), "--fps", "1", "--frames", "400"});
  CHECK_FALSE(exact.contains("divergences"));  // the closed form is stable at any Δt
  // Diverged while warming up, before any frame is drawn: still a result, with figures on.
  const auto warm = write_scene(
      dir.path(), "warm.toml",
      "name = 'warm'\nwarmup = 100\n[forces]\ndrag = 10\n[[emitter]]\nname = 'a'\nrate = 5\nspeed = 5\n"
      "lifetime = 1000\n");
  kit::test::TempDir out("ch05-warm");
  const auto drawn =
      kit::test::run_process(binary, {"--scene", warm.string(), "--fps", "1", "--frames", "5", "--integrator",
                                      "euler", "--format", "png", "--out", out.path().string()});
  INFO(drawn.err);
  CHECK(drawn.exit_code == 0);
  CHECK_THAT(drawn.out, ContainsSubstring("No frame was rendered"));
  CHECK(fs::exists(out.path() / "counts.png"));
}

TEST_CASE("chapter 5: a rerun into the same folder animates its own frames, not an earlier run's") {
  kit::test::TempDir out("ch05-rerun");
  const std::vector<std::string> small{"--width", "32", "--height", "18", "--format", "png"};
  auto with_frames = [&](const std::string& n) {
    auto v = small;
    v.insert(v.end(), {"--frames", n});
    return v;
  };
  run_chapter(with_frames("12"), out.path());
  const json second = run_chapter(with_frames("4"), out.path());
  CHECK(kit::test::files_under(out.path() / "frames").size() == 4);
  CHECK_THAT(slurp(out.path() / "play.gp"), ContainsSubstring("[i = 0:3]"));
  CHECK(second["frames"]["count"] == 4);
}

TEST_CASE("chapter 5: a texture that is not there is a usage error before anything is written") {
  kit::test::TempDir dir("ch05-texture");
  const auto scene = write_scene(dir.path(), "textured.toml",
                                 "name = 'x'\n[[emitter]]\nname = 'a'\ntexture = 'missing.png'\n");
  kit::test::expect_usage_errors(binary, {{{"--scene", scene.string()}, "emitter[0].texture"},
                                          {{"--scene", scene.string(), "--no-plot"}, "missing.png"}});
}

TEST_CASE("chapter 5: without ffmpeg the chapter says so and keeps the PNG frames") {
  kit::test::TempDir bin("ch05-path"), out("ch05-noffmpeg");
  fs::create_symlink("/usr/bin/gnuplot", bin.path() / "gnuplot");
  const auto result =
      kit::test::run_process("env", {"PATH=" + bin.path().string(), binary, "--frames", "4", "--width", "64",
                                     "--height", "36", "--format", "png", "--out", out.path().string()});
  INFO(result.err);
  REQUIRE(result.exit_code == 0);
  CHECK_THAT(result.out, ContainsSubstring("ffmpeg not found"));
  CHECK(fs::exists(out.path() / "frames" / "frame_0003.png"));
  CHECK_FALSE(fs::exists(out.path() / "animation.mp4"));
}

// The particle system with the reference exercises (solutions/): the properties a scene relies on.
namespace {
kit::SpriteScene jet_scene() {
  return kit::parse_sprite_scene("name = 'jet'\n[[emitter]]\nname = 'jet'\nshape = 'cone'\nangle_deg = 20\n"
                                 "rate = { mean = 40, variance = 10 }\nspeed = { mean = 5, variance = 1 }\n"
                                 "lifetime = { mean = 1.0, variance = 0.5 }\n",
                                 "jet.toml");
}
}  // namespace

TEST_CASE("sprite system: a particle lives exactly ceil(lifetime / dt) updates", "[system]") {
  const kit::SpriteScene scene = jet_scene();
  kit::SpriteSystem system(scene, 100000, 30, 3, kit::Integrator::exact,
                           kit::student_kernels(scene.emitters[0]));
  std::map<std::uint32_t, std::pair<long, float>> born;  // id -> frame, lifetime
  long checked = 0, ambiguous = 0;
  std::map<std::uint32_t, bool> seen;
  for (int f = 0; f < 120; ++f) {
    system.step();
    seen.clear();
    const auto& ps = system.particles();
    for (std::size_t i = 0; i < ps.size(); ++i) {
      seen[ps.id[i]] = true;
      born.try_emplace(ps.id[i], f, ps.lifetime[i]);
    }
    for (auto it = born.begin(); it != born.end();) {
      if (seen.count(it->first)) {
        ++it;
        continue;
      }
      // Died in frame f: it was updated f − born + 1 times.
      const double updates = double(f - it->second.first + 1), steps = double(it->second.second) * 30.0;
      if (std::abs(steps - std::round(steps)) < 1e-4) {
        ++ambiguous;  // float age on a frame boundary: either frame is right
      } else {
        CHECK(updates == std::ceil(steps));
        ++checked;
      }
      it = born.erase(it);
    }
  }
  CHECK(checked > 1000);
  CHECK(ambiguous < checked / 100);
}

TEST_CASE("sprite system: counts are conserved: alive = emitted − dead after every frame, bursts included",
          "[system]") {
  kit::SpriteScene scene = jet_scene();
  scene.emitters[0].on_death = 1;
  kit::Emitter burst;
  burst.name = "burst", burst.burst_only = true, burst.rate = {20, 5}, burst.speed = {3, 1};
  burst.lifetime = {0.5, 0.2};
  scene.emitters.push_back(burst);
  kit::SpriteSystem system(scene, 3000, 30, 5, kit::Integrator::midpoint,
                           kit::student_kernels(scene.emitters[0]));  // small: some are dropped
  long emitted = 0, died = 0, dropped = 0;
  for (int f = 0; f < 90; ++f) {
    const kit::FrameCounts c = system.step();
    emitted += c.emitted, died += c.died, dropped += c.dropped;
    REQUIRE(c.alive == emitted - died);
    REQUIRE(system.totals().alive() == c.alive);
  }
  CHECK(died > 0);
  CHECK(dropped > 0);
  CHECK(system.totals().dropped == dropped);
}

TEST_CASE("sprite system: the same seed gives identical particles, another seed different ones", "[system]") {
  const kit::SpriteScene scene = jet_scene();
  const auto positions = [&](std::uint64_t seed) {
    kit::SpriteSystem system(scene, 100000, 30, seed, kit::Integrator::midpoint,
                             kit::student_kernels(scene.emitters[0]));
    for (int f = 0; f < 30; ++f) system.step();
    const auto& ps = system.particles();
    return std::vector<float>(ps.x.begin(), ps.x.begin() + long(ps.size()));
  };
  CHECK(positions(42) == positions(42));
  CHECK(positions(42) != positions(43));
}
