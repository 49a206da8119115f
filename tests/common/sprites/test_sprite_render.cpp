// The chapter 5 sprite renderer: compositing rules, camera, clipping, textures, PNG output,
// contact sheets and the optional ffmpeg step.
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>
#include <kit_catch.hpp>

#include <kit/base/usage.hpp>
#include <kit/render/animation.hpp>
#include <kit/render/camera.hpp>
#include <kit/render/contact_sheet.hpp>
#include <kit/render/image.hpp>
#include <kit/sprites/blend.hpp>
#include <kit/sprites/particles.hpp>
#include <kit/sprites/sprite_renderer.hpp>
#include <kit/sprites/sprite_scene.hpp>
#include <kit/sprites/sprite_texture.hpp>

#include "process.hpp"

namespace {

// A fully opaque white texture (write_png stores RGB; a PNG without alpha reads as opaque), so
// a sprite's alpha is exactly its particle's.
std::string opaque_white_png(const kit::test::TempDir& dir) {
  const auto path = dir.path() / "white.png";
  kit::write_png(kit::Image(4, 4, {1, 1, 1}), path);
  return path.string();
}

// Looking from z = 10 at the origin with a 90° field of view: focal length = height/2 pixels.
kit::SpriteScene scene_with(std::vector<kit::Emitter> emitters, kit::Colour background = {0.5, 0.5, 0.5}) {
  kit::SpriteScene scene;
  scene.camera = {{0, 0, 10}, {0, 0, 0}, 90};
  scene.background = background;
  scene.emitters = std::move(emitters);
  return scene;
}

kit::Emitter emitter(kit::Blend blend, std::string texture) {
  kit::Emitter e;
  e.blend = blend;
  e.texture = std::move(texture);
  return e;
}

kit::ParticleSpawn particle(float x, float y, float z, float size, kit::Rgb colour, float alpha,
                            std::uint8_t from) {
  kit::ParticleSpawn p;
  p.x = x, p.y = y, p.z = z, p.size = size;
  p.r = colour.r, p.g = colour.g, p.b = colour.b, p.alpha = alpha;
  p.emitter = from;
  return p;
}

kit::Particles particles_of(const std::vector<kit::ParticleSpawn>& spawns) {
  kit::Particles particles;
  particles.reserve(spawns.size() + 1);
  for (const auto& spawn : spawns) particles.add(spawn);
  return particles;
}

bool every_pixel_is(const kit::Image& image, float r, float g, float b) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.pixel(x, y);
      if (p[0] != r || p[1] != g || p[2] != b) return false;
    }
  return true;
}

double total_light(const kit::Image& image, const kit::Colour& background) {
  double sum = 0;
  for (std::size_t k = 0; k < image.rgb.size(); ++k) sum += image.rgb[k] - background[k % 3];
  return sum;
}

}  // namespace

TEST_CASE("over and additive give the exact expected pixel for dyadic colours and alphas",
          "[sprite-render]") {
  float over[3] = {0.5f, 0.5f, 0.5f};
  kit::blend_over(over, {1.0f, 0.5f, 0.0f}, 0.25f);  // 0.25·c + 0.75·0.5
  CHECK(over[0] == 0.625f);
  CHECK(over[1] == 0.5f);
  CHECK(over[2] == 0.375f);
  float added[3] = {0.5f, 0.5f, 0.5f};
  kit::blend_additive(added, {1.0f, 0.5f, 0.0f}, 0.25f);  // 0.5 + 0.25·c
  CHECK(added[0] == 0.75f);
  CHECK(added[1] == 0.625f);
  CHECK(added[2] == 0.5f);
  float bright[3] = {1.0f, 1.0f, 1.0f};
  kit::blend_additive(bright, {1.0f, 1.0f, 1.0f}, 1.0f);
  CHECK(bright[0] == 2.0f);  // not clamped until output
}

TEST_CASE("a frame-filling sprite renders the exact composite and the PNG stores the rounded bytes",
          "[sprite-render]") {
  kit::test::TempDir dir("sprite-exact");
  const std::string white = opaque_white_png(dir);
  const auto scene = scene_with({emitter(kit::Blend::over, white), emitter(kit::Blend::additive, white)});
  kit::SpriteRenderer renderer(scene, 8, 8);
  // 100 m at 10 m depth is 40 pixels: every pixel of the 8 × 8 image is wholly covered.
  for (std::uint8_t which : {0, 1}) {
    const auto particles = particles_of({particle(0, 0, 0, 100, {1.0f, 0.5f, 0.0f}, 0.25f, which)});
    kit::Image image;
    const kit::RenderStats stats = renderer.render(particles, image);
    CHECK(stats.sprites_drawn == 1);
    CHECK(stats.pixels_blended == 64);
    const auto path = dir.path() / (which == 0 ? "over.png" : "additive.png");
    kit::write_png(image, path);
    const kit::Rgba8 back = kit::read_png(path);
    REQUIRE(back.width == 8);
    REQUIRE(back.height == 8);
    if (which == 0) {
      CHECK(every_pixel_is(image, 0.625f, 0.5f, 0.375f));
      // 255·0.625 = 159.375 → 159, 255·0.5 = 127.5 → 128 (half away from zero), 255·0.375 = 95.625 → 96
      CHECK(back.rgba[0] == 159);
      CHECK(back.rgba[1] == 128);
      CHECK(back.rgba[2] == 96);
    } else {
      CHECK(every_pixel_is(image, 0.75f, 0.625f, 0.5f));
      CHECK(back.rgba[0] == 191);  // 191.25
      CHECK(back.rgba[1] == 159);
      CHECK(back.rgba[2] == 128);
    }
    CHECK(back.rgba[3] == 255);
    CHECK(back.rgba[4 * 63] == back.rgba[0]);  // the last pixel too
  }
  CHECK(kit::to_byte(1.5f) == 255);
  CHECK(kit::to_byte(-0.2f) == 0);
  CHECK(kit::to_byte(std::nanf("")) == 0);
}

TEST_CASE("over is order dependent, so sprites are sorted back to front: the nearer opaque one wins",
          "[sprite-render]") {
  float a_then_b[3] = {0, 0, 0}, b_then_a[3] = {0, 0, 0};
  kit::blend_over(a_then_b, {1, 0, 0}, 0.5f), kit::blend_over(a_then_b, {0, 0, 1}, 0.5f);
  kit::blend_over(b_then_a, {0, 0, 1}, 0.5f), kit::blend_over(b_then_a, {1, 0, 0}, 0.5f);
  CHECK(a_then_b[0] != b_then_a[0]);

  kit::test::TempDir dir("sprite-order");
  const auto scene = scene_with({emitter(kit::Blend::over, opaque_white_png(dir))});
  kit::SpriteRenderer renderer(scene, 16, 16);
  const auto far_red = particle(0, 0, 0, 4, {1, 0, 0}, 1, 0);    // depth 10
  const auto near_blue = particle(0, 0, 5, 2, {0, 0, 1}, 1, 0);  // depth 5
  for (const auto& order : {std::vector{far_red, near_blue}, std::vector{near_blue, far_red}}) {
    kit::Image image;
    renderer.render(particles_of(order), image);
    const float* centre = image.pixel(8, 8);
    CHECK(centre[0] == 0.0f);
    CHECK(centre[1] == 0.0f);
    CHECK(centre[2] == 1.0f);
  }
}

TEST_CASE("additive sprites are order independent: swapping the particles gives the same image",
          "[sprite-render]") {
  kit::test::TempDir dir("sprite-additive");
  SECTION("dyadic values, whole pixels: bit for bit") {
    const auto scene = scene_with({emitter(kit::Blend::additive, opaque_white_png(dir))}, {0, 0, 0});
    kit::SpriteRenderer renderer(scene, 8, 8);
    const auto a = particle(0, 0, 0, 100, {1.0f, 0.5f, 0.25f}, 0.25f, 0);
    const auto b = particle(0, 0, 1, 100, {0.5f, 1.0f, 0.75f}, 0.5f, 0);
    kit::Image ab, ba;
    renderer.render(particles_of({a, b}), ab);
    renderer.render(particles_of({b, a}), ba);
    CHECK(ab.rgb == ba.rgb);
    CHECK(every_pixel_is(ab, 0.5f, 0.625f, 0.4375f));
  }
  SECTION("soft sprites overlapping in part: equal up to float rounding") {
    const auto scene = scene_with({emitter(kit::Blend::additive, "spark")}, {0, 0, 0});
    kit::SpriteRenderer renderer(scene, 64, 48);
    std::vector<kit::ParticleSpawn> spawns{particle(-1.3f, 0.2f, 0, 3, {1, 0.6f, 0.2f}, 0.7f, 0),
                                           particle(0.4f, -0.5f, 1, 2.5f, {0.2f, 0.5f, 1}, 0.9f, 0),
                                           particle(0.1f, 0.3f, -2, 4, {0.9f, 0.9f, 0.3f}, 0.4f, 0)};
    kit::Image forward, backward;
    renderer.render(particles_of(spawns), forward);
    renderer.render(particles_of(std::vector<kit::ParticleSpawn>(spawns.rbegin(), spawns.rend())), backward);
    double largest = 0;
    for (std::size_t k = 0; k < forward.rgb.size(); ++k)
      largest = std::max(largest, static_cast<double>(std::abs(forward.rgb[k] - backward.rgb[k])));
    CHECK(largest < 1e-6);
    CHECK(total_light(forward, {0, 0, 0}) > 1);
  }
}

TEST_CASE("the camera projects its target to the image centre and a point above it to a smaller row",
          "[sprite-render]") {
  kit::Camera camera{{1, 2, 10}, {1, 2, 0}, 45};
  const kit::Pinhole pinhole(camera, 64, 48);
  const auto target = pinhole.project(1, 2, 0);
  REQUIRE(target);
  CHECK(target->px == Approx(32.0).margin(1e-9));
  CHECK(target->py == Approx(24.0).margin(1e-9));
  CHECK(target->depth == Approx(10.0));
  const auto above = pinhole.project(1, 3, 0);
  REQUIRE(above);
  CHECK(above->py < target->py);
  CHECK(above->px == Approx(32.0).margin(1e-9));
  const auto right = pinhole.project(2, 2, 0);  // looking down −z, +x is to the right
  REQUIRE(right);
  CHECK(right->px > target->px);
  // One metre up at 10 m depth is focal/10 pixels: focal = (48/2)/tan(22.5°).
  const double focal = 24.0 / std::tan(22.5 * std::numbers::pi / 180);
  CHECK(target->py - above->py == Approx(focal / 10));
  CHECK_FALSE(pinhole.project(1, 2, 20));    // behind the camera
  CHECK_FALSE(pinhole.project(1, 2, 9.99));  // nearer than the near plane
  CHECK_THROWS_AS(kit::Pinhole(kit::Camera{{0, 0, 0}, {0, 0, 0}, 45}, 8, 8), kit::UsageError);
  CHECK_THROWS_AS(kit::Pinhole(kit::Camera{{0, 0, 1}, {0, 0, 0}, 180}, 8, 8), kit::UsageError);
  // Looking straight down still has a frame.
  const kit::Pinhole down(kit::Camera{{0, 10, 0}, {0, 0, 0}, 60}, 8, 8);
  const auto ground = down.project(0, 0, 0);
  REQUIRE(ground);
  CHECK(ground->px == Approx(4.0));
}

TEST_CASE("pixels per metre is the focal length over depth, and a sprite is that many pixels wide",
          "[sprite-render]") {
  const kit::Pinhole pinhole(kit::Camera{{0, 0, 10}, {0, 0, 0}, 90}, 100, 100);
  CHECK(pinhole.focal_px() == Approx(50.0));
  CHECK(pinhole.pixels_per_metre(10) == Approx(5.0));
  CHECK(pinhole.pixels_per_metre(20) == Approx(2.5));

  kit::test::TempDir dir("sprite-scale");
  const auto scene = scene_with({emitter(kit::Blend::over, opaque_white_png(dir))}, {0, 0, 0});
  kit::SpriteRenderer renderer(scene, 100, 100);
  for (const auto& [z, lit] :
       {std::pair{0.0f, 400}, std::pair{-10.0f, 100}}) {  // 4 m: 20 px at 10 m, 10 px at 20 m
    kit::Image image;
    renderer.render(particles_of({particle(0, 0, z, 4, {1, 1, 1}, 1, 0)}), image);
    int count = 0;
    for (int y = 0; y < 100; ++y)
      for (int x = 0; x < 100; ++x) count += image.pixel(x, y)[0] > 0.5f;
    CHECK(count == lit);
  }
}

TEST_CASE("a sprite behind the camera is culled and leaves the background", "[sprite-render]") {
  const auto scene = scene_with({emitter(kit::Blend::additive, "soft")});
  kit::SpriteRenderer renderer(scene, 16, 16);
  kit::Image image;
  const auto stats = renderer.render(particles_of({particle(0, 0, 12, 1, {1, 1, 1}, 1, 0)}), image);
  CHECK(stats.sprites_culled == 1);
  CHECK(stats.sprites_drawn == 0);
  CHECK(stats.pixels_blended == 0);
  CHECK(every_pixel_is(image, 0.5f, 0.5f, 0.5f));
}

TEST_CASE("sprites partly or wholly outside the image are clipped, never written out of bounds",
          "[sprite-render]") {
  const auto scene =
      scene_with({emitter(kit::Blend::over, "soft"), emitter(kit::Blend::additive, "spark")}, {0, 0, 0});
  kit::SpriteRenderer renderer(scene, 32, 24);
  kit::Image image;
  const auto stats =
      renderer.render(particles_of({
                          particle(-4.5f, 3.5f, 0, 3, {1, 1, 1}, 1, 0),  // over the top-left corner
                          particle(5, -4, 0, 4, {1, 1, 1}, 1, 1),        // over the bottom-right corner
                          particle(0, 0, 9.9f, 50, {1, 1, 1}, 1, 1),     // just past the near plane, huge
                          particle(100, 0, 0, 1, {1, 1, 1}, 1, 0),       // wholly off to the right
                      }),
                      image);
  CHECK(stats.sprites_drawn == 3);
  CHECK(stats.sprites_culled == 1);
  CHECK(stats.pixels_blended <= 3 * 32 * 24);
  CHECK(image.pixel(0, 0)[0] > 0);
  CHECK(image.pixel(31, 23)[0] > 0);
}

TEST_CASE("a sprite smaller than a pixel still adds its area's light, wherever it sits in the pixel",
          "[sprite-render]") {
  const auto scene = scene_with({emitter(kit::Blend::additive, "soft")}, {0, 0, 0});
  kit::SpriteRenderer renderer(scene, 64, 64);  // 3.2 px/m at 10 m
  const float size = 0.1f;                      // 0.32 px
  const double edge = size * renderer.camera().pixels_per_metre(10);
  const double mean_alpha = kit::mip_levels(kit::builtin_texture("soft")).back().rgba[3];
  std::vector<double> totals;
  for (float dx : {0.0f, 0.05f, 0.11f, 0.157f}) {  // slides across pixel boundaries
    kit::Image image;
    const auto stats = renderer.render(particles_of({particle(dx, 0.03f, 0, size, {1, 1, 1}, 1, 0)}), image);
    CHECK(stats.sprites_drawn == 1);
    totals.push_back(total_light(image, {0, 0, 0}) / 3);
  }
  for (double total : totals) CHECK(total == Approx(edge * edge * mean_alpha).epsilon(1e-4));
  CHECK(mean_alpha > 0.05);
}

TEST_CASE("write_png writes a valid PNG and, when it cannot, throws naming the path and leaves no file",
          "[sprite-render]") {
  kit::test::TempDir dir("sprite-png");
  kit::Image image(5, 3, {0, 0, 0});
  image.pixel(4, 0)[0] = 1;  // top right red
  image.pixel(0, 2)[2] = 1;  // bottom left blue
  const auto path = dir.path() / "small.png";
  kit::write_png(image, path);
  const kit::Rgba8 back = kit::read_png(path);
  CHECK(back.width == 5);
  CHECK(back.height == 3);
  CHECK(back.rgba[4 * 4 + 0] == 255);
  CHECK(back.rgba[4 * 10 + 2] == 255);
  CHECK(back.rgba[4 * 10 + 0] == 0);
  CHECK(kit::test::files_under(dir.path()).size() == 1);

  const auto locked = dir.path() / "locked";
  std::filesystem::create_directory(locked);
  std::filesystem::permissions(locked,
                               std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  const bool can_still_write = ::access(locked.c_str(), W_OK) == 0;  // root ignores permissions
  const auto missing = dir.path() / "no-such-folder" / "frame.png";
  CHECK_THROWS_WITH(kit::write_png(image, missing), ContainsSubstring("no-such-folder"));
  if (!can_still_write)
    CHECK_THROWS_WITH(kit::write_png(image, locked / "frame.png"), ContainsSubstring("locked"));
  std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
  CHECK(kit::test::files_under(dir.path()).size() == 1);
  CHECK_THROWS_AS(kit::read_png(missing), std::runtime_error);
}

TEST_CASE("a contact sheet tiles the frames in rows with gaps around and between them", "[sprite-render]") {
  std::vector<kit::Image> frames;
  for (int n = 0; n < 5; ++n) frames.emplace_back(10, 6, kit::Colour{0.1 * n, 1, 0});
  const kit::Image sheet = kit::contact_sheet(frames, 3, 2);
  CHECK(sheet.width == 3 * 10 + 4 * 2);
  CHECK(sheet.height == 2 * 6 + 3 * 2);
  CHECK(sheet.pixel(0, 0)[1] == Approx(kit::contact_sheet_background[1]));
  CHECK(sheet.pixel(2 + 12 + 0, 2 + 8 + 0)[0] == Approx(0.4));  // frame 4: row 1, column 1
  CHECK(sheet.pixel(2 + 24 + 5, 2 + 8 + 3)[1] == Approx(kit::contact_sheet_background[1]));  // no frame 5
  const kit::Image one_row = kit::contact_sheet(frames, 8, 0);
  CHECK(one_row.width == 50);
  CHECK(one_row.height == 6);
  CHECK_THROWS_AS(kit::contact_sheet({}, 3, 2), std::invalid_argument);
}

TEST_CASE("every built-in texture exists, has alpha in [0, 1], a bright centre and a clear border",
          "[sprite-render]") {
  for (std::string_view name : kit::builtin_texture_names) {
    INFO(name);
    const kit::Texture texture = kit::builtin_texture(name);
    REQUIRE(texture.width > 8);
    REQUIRE(texture.rgba.size() ==
            4 * static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height));
    for (float value : texture.rgba) CHECK((value >= 0 && value <= 1));
    float centre[4], corner[4];
    kit::sample_bilinear(texture, 0.5f, 0.5f, centre);
    kit::sample_bilinear(texture, 0.0f, 0.0f, corner);
    CHECK(centre[3] > 0.5f);
    CHECK(corner[3] < 0.01f);
    CHECK(kit::builtin_texture(name).rgba == texture.rgba);  // deterministic
    const auto mips = kit::mip_levels(texture);
    CHECK(mips.back().width == 1);
    CHECK(mips.back().height == 1);
  }
}

TEST_CASE("an unknown texture name or unreadable PNG is a usage error naming it and the built-ins",
          "[sprite-render]") {
  CHECK_THROWS_AS(kit::builtin_texture("sparkle"), kit::UsageError);
  CHECK_THROWS_WITH(kit::texture_for("sparkle"),
                    ContainsSubstring("sparkle") && ContainsSubstring("soft, spark, flake, smoke"));
  CHECK_THROWS_WITH(kit::texture_for("/no/such/texture.png"),
                    ContainsSubstring("/no/such/texture.png") && ContainsSubstring("soft"));
  CHECK_THROWS_AS(kit::SpriteRenderer(scene_with({emitter(kit::Blend::over, "sparkle")}), 8, 8),
                  kit::UsageError);
  CHECK(kit::texture_for("flake").width == 64);
}

TEST_CASE("without ffmpeg on PATH, encode_animation writes nothing and says how to get the videos",
          "[sprite-render]") {
  kit::test::TempDir dir("sprite-no-ffmpeg");
  const auto empty_bin = dir.path() / "bin";
  std::filesystem::create_directory(empty_bin);
  const char* old = std::getenv("PATH");
  const std::optional<std::string> saved = old ? std::optional<std::string>(old) : std::nullopt;
  ::setenv("PATH", empty_bin.c_str(), 1);
  const auto result = kit::encode_animation(dir.path() / "frames" / "frame_%04d.png", 30,
                                            dir.path() / "run.mp4", dir.path() / "run.gif");
  if (saved)
    ::setenv("PATH", saved->c_str(), 1);
  else
    ::unsetenv("PATH");
  CHECK(result.files.empty());
  CHECK_THAT(result.note, ContainsSubstring("ffmpeg not found") && ContainsSubstring("./kit deps") &&
                              ContainsSubstring((dir.path() / "frames").string()));
  CHECK(kit::test::files_under(dir.path()).empty());
}

TEST_CASE("with ffmpeg, encode_animation writes a non-empty MP4 and GIF and no temporaries; a failure leaves "
          "nothing",
          "[sprite-render]") {
  if (kit::find_ffmpeg().empty()) {
    WARN("ffmpeg is not on PATH: encoding not checked");
    return;
  }
  kit::test::TempDir dir("sprite-ffmpeg");
  const auto scene = scene_with({emitter(kit::Blend::additive, "spark")}, {0, 0, 0});
  kit::SpriteRenderer renderer(scene, 33, 25);  // odd sizes: the MP4 must pad
  kit::Image frame;
  for (int n = 0; n < 4; ++n) {
    renderer.render(
        particles_of({particle(-1.0f + 0.5f * static_cast<float>(n), 0, 0, 2, {1, 0.8f, 0.3f}, 1, 0)}),
        frame);
    kit::write_png(frame, dir.path() / fmt::format("frame_{:04d}.png", n));
  }
  const auto mp4 = dir.path() / "run.mp4", gif = dir.path() / "run.gif";
  const auto result = kit::encode_animation(dir.path() / "frame_%04d.png", 12, mp4, gif);
  INFO(result.note);
  CHECK(result.note.empty());
  CHECK(result.files == std::vector<std::filesystem::path>{mp4, gif});
  CHECK(std::filesystem::file_size(mp4) > 0);
  CHECK(std::filesystem::file_size(gif) > 0);
  CHECK(kit::test::files_under(dir.path()).size() == 6);  // 4 frames + 2 videos

  const auto failed = kit::encode_animation(dir.path() / "missing_%04d.png", 12, dir.path() / "bad.mp4",
                                            dir.path() / "bad.gif");
  CHECK(failed.files.empty());
  CHECK_THAT(failed.note, ContainsSubstring("exit status") && ContainsSubstring("bad.mp4") &&
                              ContainsSubstring("bad.gif"));
  CHECK(kit::test::files_under(dir.path()).size() == 6);
}
