// The cloth's outputs (chapter 6): the OBJ mesh written and read back, its vertex normals, the
// cloth renderer (colours, a diverged sheet) and the frame writer.
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <kit_catch.hpp>

#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_renderer.hpp>
#include <kit/cloth/cloth_scene.hpp>
#include <kit/cloth/obj_mesh.hpp>
#include <kit/render/frame_writer.hpp>
#include <kit/render/image.hpp>

#include "process.hpp"

namespace {

// The rest positions, computed here: ClothGrid::rest_positions is not what is tested.
kit::NodeArray flat_positions(const kit::ClothGrid& grid) {
  kit::NodeArray x(grid.nodes(), 3);
  for (int j = 0; j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) x.row(grid.index(i, j)) = grid.rest_position(i, j).transpose();
  return x;
}

// A 5 × 4 sheet bent out of its plane (u = x, v = z; y lifted by a bump), so normals vary.
kit::ClothGrid bent_grid() {
  kit::ClothGrid grid;
  grid.nx = 5, grid.ny = 4, grid.width = 1.2, grid.height = 0.9;
  grid.origin = {-0.6, 1.0, -0.45};
  return grid;
}
kit::NodeArray bent_positions(const kit::ClothGrid& grid) {
  kit::NodeArray x = flat_positions(grid);
  for (long k = 0; k < x.rows(); ++k)
    x(k, 1) += 0.3 * std::sin(3 * x(k, 0)) * std::cos(2 * x(k, 2)) + 1e-10 * k;
  return x;
}

void write_text(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

// A vertical 1 m sheet in the plane z = 0 facing a camera that looks along −z from z = 3:
// u = x, v = y, so u × v = +z points at the camera (its front shows).
kit::ClothScene facing_scene(kit::ClothGrid& grid) {
  grid.nx = 9, grid.ny = 9, grid.width = 1, grid.height = 1;
  grid.origin = {-0.5, 0.0, 0.0};
  grid.u = {1, 0, 0}, grid.v = {0, 1, 0};
  kit::ClothScene scene;
  scene.grid = grid;
  scene.camera.position = {0, 0.5, 3}, scene.camera.target = {0, 0.5, 0}, scene.camera.fov_deg = 40;
  return scene;
}

bool near_colour(const float* pixel, const kit::Colour& colour, double tolerance) {
  return std::abs(pixel[0] - colour[0]) <= tolerance && std::abs(pixel[1] - colour[1]) <= tolerance &&
         std::abs(pixel[2] - colour[2]) <= tolerance;
}

}  // namespace

TEST_CASE("a bent sheet's OBJ reads back: counts, positions, unit normals agreeing with its faces",
          "[cloth]") {
  const kit::test::TempDir dir("cloth-obj");
  const kit::ClothGrid grid = bent_grid();
  const kit::NodeArray x = bent_positions(grid);
  const auto path = dir.path() / "sheet.obj";
  kit::write_cloth_obj(path, grid, x);
  const kit::ObjMesh mesh = kit::read_obj(path);
  REQUIRE(mesh.positions.size() == 20);
  REQUIRE(mesh.normals.size() == 20);
  REQUIRE(mesh.faces.size() == std::size_t(2 * (grid.nx - 1) * (grid.ny - 1)));
  for (long k = 0; k < x.rows(); ++k) {
    // %.9g keeps 9 significant digits: each coordinate within half a unit of the 9th, ≤ 5e-9·|x|.
    for (int axis = 0; axis < 3; ++axis)
      CHECK(std::abs(mesh.positions[std::size_t(k)][axis] - x(k, axis)) <= 5e-9 * std::abs(x(k, axis)));
    CHECK(mesh.normals[std::size_t(k)].norm() == Approx(1).margin(1e-8));
  }
  // Each face's own normal (from its winding) points the way its vertices' normals do.
  for (const auto& face : mesh.faces) {
    const kit::Vec3 &a = mesh.positions[std::size_t(face[0])], &b = mesh.positions[std::size_t(face[1])],
                    &c = mesh.positions[std::size_t(face[2])];
    const kit::Vec3 n = (b - a).cross(c - a).normalized();
    for (const int v : face) CHECK(n.dot(mesh.normals[std::size_t(v)]) > 0.5);
    // and the winding keeps the sheet's orientation: u × v here is −y, the bump is gentle.
    CHECK(n.dot(grid.u.cross(grid.v)) > 0.3);
  }
}

TEST_CASE("read_obj refuses malformed lines and indices out of range, naming the line", "[cloth]") {
  const kit::test::TempDir dir("cloth-obj-bad");
  const std::string vertices = "# ok\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n";
  const auto path = dir.path() / "m.obj";
  write_text(path, vertices + "f 1//1 2//2 3//3\n");
  CHECK(kit::read_obj(path).faces.size() == 1);
  const std::vector<std::string> bad{
      "f 1//1 2//2 4//4\n",  // vertex 4 does not exist
      "f 0 1 2\n",           // OBJ indices start at 1
      "f 1//1 2//2\n",       // not a triangle
      "f 1//1 2//2 3//3 1//1\n",
      "f 1//2 2//2 3//3\n",     // a normal that is not its vertex's
      "f 1/1/1 2/2/2 3/3/3\n",  // texture coordinates are not written, so not read
      "v 1 2\n",
      "v 1 2 3 4\n",
      "v 1 2 x\n",
      "vn 0 0 1e\n",
      "vt 0 0\n",
      "usemtl cloth\n",
  };
  for (const std::string& line : bad) {
    INFO(line);
    write_text(path, vertices + line);
    CHECK_THROWS_AS(kit::read_obj(path), std::runtime_error);
    try {
      kit::read_obj(path);
    } catch (const std::runtime_error& e) {
      CHECK_THAT(e.what(), ContainsSubstring(":8:"));
    }
  }
  write_text(path, "v 0 0 0\nv 1 0 0\nvn 0 0 1\n");  // normals neither absent nor one per vertex
  CHECK_THROWS_AS(kit::read_obj(path), std::runtime_error);
  CHECK_THROWS_AS(kit::read_obj(dir.path() / "missing.obj"), std::runtime_error);
}

TEST_CASE("a flat sheet's vertex normals are its u x v; a collapsed one falls back to it", "[cloth]") {
  kit::ClothGrid grid;
  grid.nx = 6, grid.ny = 3, grid.width = 2, grid.height = 0.5;
  grid.u = kit::Vec3(1, 0, 1).normalized(), grid.v = {0, 1, 0};
  const kit::Vec3 expected = grid.u.cross(grid.v).normalized();
  kit::NodeArray x = flat_positions(grid);
  kit::NodeArray n = kit::vertex_normals(grid, x);
  for (long k = 0; k < n.rows(); ++k) CHECK((n.row(k).transpose() - expected).norm() < 1e-12);
  // Flipping v flips every normal: the winding follows the grid, not the world.
  grid.v = -grid.v;
  x = flat_positions(grid);
  n = kit::vertex_normals(grid, x);
  for (long k = 0; k < n.rows(); ++k) CHECK((n.row(k).transpose() + expected).norm() < 1e-12);
  // All nodes at one point: no triangle has an area, every node gets u × v.
  n = kit::vertex_normals(grid, kit::NodeArray::Zero(grid.nodes(), 3));
  for (long k = 0; k < n.rows(); ++k) CHECK((n.row(k).transpose() + expected).norm() < 1e-12);
  CHECK_THROWS_AS(kit::vertex_normals(grid, kit::NodeArray::Zero(5, 3)), std::invalid_argument);
}

TEST_CASE("a sheet facing the camera fills the centre with its front colour; the corner is sky", "[cloth]") {
  kit::ClothGrid grid;
  kit::ClothScene scene = facing_scene(grid);
  kit::ClothRenderStats stats;
  const kit::Image image = kit::render_cloth(grid, flat_positions(grid), scene, 160, 120, &stats);
  CHECK(stats.triangles_drawn == 2 * 8 * 8);
  CHECK(stats.triangles_skipped == 0);
  const float* centre = image.pixel(80, 60);
  // Lit by the key light and the ambient: the front colour times a factor in [ambient, 1], so
  // red dominates blue (the back colour would have blue dominate).
  CHECK(centre[0] > centre[2] * 1.5f);
  const double factor = centre[0] / kit::cloth_front_colour[0];
  CHECK(factor >= kit::cloth_ambient - 1e-6);
  CHECK(factor <= 1 + 1e-6);
  CHECK(near_colour(centre,
                    {kit::cloth_front_colour[0] * factor, kit::cloth_front_colour[1] * factor,
                     kit::cloth_front_colour[2] * factor},
                    1e-5));
  // The top-left pixel's ray: camera looking along −z, focal length 60/tan 20° pixels.
  const double focal = 60 / std::tan(20 * M_PI / 180), a = (0.5 - 80) / focal, b = (60 - 0.5) / focal;
  const kit::Colour sky = kit::cloth_sky(b / std::sqrt(a * a + b * b + 1));
  CHECK(near_colour(image.pixel(0, 0), sky, 1e-6));
  CHECK(!near_colour(image.pixel(0, 0), kit::cloth_sky_bottom, 0.05));  // above the horizon: bluer
  // Seen from behind, the same sheet shows its back colour.
  scene.camera.position = {0, 0.5, -3};
  const kit::Image behind = kit::render_cloth(grid, flat_positions(grid), scene, 160, 120);
  CHECK(behind.pixel(80, 60)[2] > behind.pixel(80, 60)[0] * 1.5f);
}

TEST_CASE("the ground and a sphere are drawn, and the sheet hides what is behind it", "[cloth]") {
  kit::ClothGrid grid;
  kit::ClothScene scene = facing_scene(grid);
  scene.ground = kit::GroundCollider{-0.2, 0};
  scene.spheres.push_back({{0, 0.5, -1}, 0.3, 0});
  // The sheet moved out of view (all nodes behind the camera): the sphere shows at the centre.
  kit::NodeArray behind_camera = flat_positions(grid);
  behind_camera.col(2).array() += 10;
  const kit::Image sphere_only = kit::render_cloth(grid, behind_camera, scene, 160, 120);
  const float* centre = sphere_only.pixel(80, 60);
  CHECK(std::abs(centre[0] - centre[2]) < 0.1f);         // the sphere is grey, not the sheet's red
  CHECK(!near_colour(centre, kit::cloth_sky(0), 0.05));  // the sky behind it
  // The bottom row sees the ground, not the sky's bottom colour.
  CHECK(!near_colour(sphere_only.pixel(80, 119), kit::cloth_sky_bottom, 0.02));
  // With the sheet in front, the centre is the sheet's again.
  const kit::Image with_sheet = kit::render_cloth(grid, flat_positions(grid), scene, 160, 120);
  CHECK(with_sheet.pixel(80, 60)[0] > with_sheet.pixel(80, 60)[2] * 1.5f);
}

TEST_CASE("a diverged sheet (NaN, 1e300, nodes behind the camera) renders without throwing", "[cloth]") {
  kit::ClothGrid grid;
  kit::ClothScene scene = facing_scene(grid);
  scene.ground = kit::GroundCollider{0, 0};
  kit::NodeArray x = flat_positions(grid);
  x(3, 0) = std::numeric_limits<double>::quiet_NaN();
  x(10, 1) = 1e300;
  x(20, 2) = -1e300;
  x(30, 2) = std::numeric_limits<double>::infinity();
  x(40, 2) = 3;  // at the eye's depth: behind the near plane
  x(50, 0) = 1e12;
  kit::ClothRenderStats stats;
  kit::Image image;
  REQUIRE_NOTHROW(image = kit::render_cloth(grid, x, scene, 96, 64, &stats));
  CHECK(stats.triangles_skipped > 0);
  CHECK(stats.triangles_drawn > 0);
  CHECK(stats.triangles_drawn + stats.triangles_skipped == 2 * 8 * 8);
  for (const float value : image.rgb) REQUIRE(std::isfinite(value));
  // Every node huge: nothing drawn, the surroundings still are.
  const kit::NodeArray huge = kit::NodeArray::Constant(grid.nodes(), 3, 1e300);
  REQUIRE_NOTHROW(image = kit::render_cloth(grid, huge, scene, 96, 64, &stats));
  CHECK(stats.triangles_drawn == 0);
}

TEST_CASE("the frame writer numbers frames from 0, clears stale ones and leaves no temporary", "[cloth]") {
  const kit::test::TempDir dir("cloth-frames");
  const auto frames = dir.path() / "frames";
  std::filesystem::create_directories(frames);
  kit::write_png(kit::Image(4, 2, {0, 0, 0}), frames / "frame_0007.png");  // an earlier, longer run
  write_text(frames / "notes.txt", "kept");
  kit::FrameWriter writer(frames, 4, 2, 6, 3);
  CHECK(!std::filesystem::exists(frames / "frame_0007.png"));
  for (int k = 0; k < 6; ++k)
    CHECK(writer.write(kit::Image(4, 2, {0.1 * k, 0.5, 1})).filename() ==
          (k == 0 ? "frame_0000.png" : "frame_000" + std::to_string(k) + ".png"));
  CHECK_THROWS_AS(writer.write(kit::Image(3, 2, {0, 0, 0})), std::invalid_argument);
  CHECK(writer.frames().files.size() == 6);
  CHECK(writer.frames().sheet.size() == 3);  // frames 0, 2 and 4
  CHECK(kit::read_png(frames / "frame_0005.png").rgba[0] == kit::to_byte(0.5f));
  const auto outputs =
      kit::finish_animation(writer.frames(), 10, kit::animation_targets(dir.path(), "drape"));
  REQUIRE(outputs);
  CHECK(outputs->sheet == dir.path() / "drape_sheet.png");
  CHECK(std::filesystem::exists(outputs->sheet));
  CHECK(std::filesystem::exists(dir.path() / "drape_play.gp"));
  std::ifstream player(outputs->player);
  const std::string script((std::istreambuf_iterator<char>(player)), std::istreambuf_iterator<char>());
  CHECK_THAT(script, ContainsSubstring("frames/frame_%04d.png") && ContainsSubstring("i = 0:5"));
  for (const auto& file : kit::test::files_under(dir.path()))
    CHECK(file.filename().string().find(".tmp") == std::string::npos);
  CHECK(std::filesystem::exists(frames / "notes.txt"));
  CHECK(!kit::finish_animation(kit::FrameSequence{}, 10, kit::animation_targets(dir.path(), "none")));
}
