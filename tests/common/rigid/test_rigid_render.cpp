// Chapter 8's outputs: the body's OBJ mesh written and read back (world corners, flat outward
// faces), the rigid renderer (body colours where the body is, the backdrop elsewhere, a turned
// body, the T-handle's two parts), the default camera and the files a run writes.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <kit_catch.hpp>

#include <kit/cloth/cloth_renderer.hpp>
#include <kit/cloth/obj_mesh.hpp>
#include <kit/render/animation.hpp>
#include <kit/render/camera.hpp>
#include <kit/render/image.hpp>
#include <kit/rigid/rigid_body.hpp>
#include <kit/rigid/rigid_renderer.hpp>

#include "process.hpp"
#include "rigid_output.hpp"

using kit::Mat3;
using kit::Vec3;

namespace {

kit::RigidState placed(const Vec3& x, const Mat3& R) {
  kit::RigidState state;
  state.x = x, state.R = R, state.q = kit::Quat(R);
  return state;
}

Mat3 turned(double angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// The 8 corners of a part in the world, x + R (c + s ⊙ sides/2), s ∈ {±1}³: computed here, not
// by the code under test.
std::vector<Vec3> world_corners(const kit::BoxPart& part, const kit::RigidState& state) {
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) {
    const Vec3 sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    corners.push_back(state.x + state.R * (part.centre + 0.5 * sign.cwiseProduct(part.sides)));
  }
  return corners;
}

// Whether a pixel is `colour` lit by some factor in [ambient, 1], as a flat-shaded face is.
bool body_coloured(const float* pixel, const kit::Colour& colour) {
  const Vec3 p(pixel[0], pixel[1], pixel[2]), c(colour[0], colour[1], colour[2]);
  const double factor = p.dot(c) / c.squaredNorm();
  return factor >= kit::cloth_ambient - 1e-6 && factor <= 1 + 1e-6 && (p - factor * c).norm() < 1e-5;
}

long pixels_differing(const kit::Image& a, const kit::Image& b) {
  long count = 0;
  for (std::size_t k = 0; k < a.rgb.size(); k += 3)
    count += a.rgb[k] != b.rgb[k] || a.rgb[k + 1] != b.rgb[k + 1] || a.rgb[k + 2] != b.rgb[k + 2];
  return count;
}

// The body alone: a shape without parts leaves only the sky and the ground.
kit::RigidShape nothing() { return kit::RigidShape{}; }

}  // namespace

TEST_CASE("a turned T-handle's OBJ reads back: world corners, 12 flat outward faces a box",
          "[rigid][render]") {
  const kit::test::TempDir dir("rigid-obj");
  const kit::RigidShape shape = kit::t_handle_shape(0.5);
  REQUIRE(shape.parts.size() == 2);
  const kit::RigidState state = placed({0.3, 1.2, -0.4}, turned(0.7, {1, 2, 3}));
  const auto path = dir.path() / "t.obj";
  kit::write_rigid_obj(path, shape, state);
  const kit::ObjMesh mesh = kit::read_obj(path);
  REQUIRE(mesh.positions.size() == 24 * shape.parts.size());
  REQUIRE(mesh.normals.size() == mesh.positions.size());
  REQUIRE(mesh.faces.size() == 12 * shape.parts.size());
  for (std::size_t p = 0; p < shape.parts.size(); ++p) {
    const std::vector<Vec3> corners = world_corners(shape.parts[p], state);
    std::vector<int> uses(8, 0);
    // Part p's 24 vertices are its corners, each on 3 faces.
    for (std::size_t v = 24 * p; v < 24 * (p + 1); ++v) {
      const auto nearest =
          std::min_element(corners.begin(), corners.end(), [&](const Vec3& a, const Vec3& b) {
            return (a - mesh.positions[v]).norm() < (b - mesh.positions[v]).norm();
          });
      CHECK((*nearest - mesh.positions[v]).norm() <= 1e-9);
      ++uses[std::size_t(nearest - corners.begin())];
    }
    for (const int count : uses) CHECK(count == 3);
  }
  for (const auto& face : mesh.faces) {
    const Vec3 &a = mesh.positions[std::size_t(face[0])], &b = mesh.positions[std::size_t(face[1])],
               &c = mesh.positions[std::size_t(face[2])];
    const Vec3& n = mesh.normals[std::size_t(face[0])];
    CHECK(n.norm() == Approx(1).margin(1e-12));
    // Flat: the three vertices carry one normal, that of the triangle's plane.
    for (const int v : face) CHECK((mesh.normals[std::size_t(v)] - n).norm() < 1e-12);
    const Vec3 winding = (b - a).cross(c - a);
    CHECK(winding.normalized().dot(n) == Approx(1).margin(1e-9));  // counter-clockwise seen from outside
    // Outward: from the centre of the box it bounds towards the face.
    const kit::BoxPart& part = shape.parts[std::size_t(face[0]) / 24];
    const Vec3 box_centre = state.x + state.R * part.centre;
    CHECK(n.dot((a + b + c) / 3 - box_centre) > 0);
  }
}

TEST_CASE("a box on the ground shows its colour where it is, the sky and the ground elsewhere",
          "[rigid][render]") {
  const kit::RigidShape box = kit::box_shape(1.0, {0.4, 0.2, 0.3});
  const kit::RigidState resting = placed({0, 0.1, 0}, Mat3::Identity());
  const kit::Camera camera = kit::rigid_camera(box, {resting}, true);
  const int width = 160, height = 120;
  const kit::Image image = kit::render_rigid(box, resting, camera, width, height);
  const kit::Image backdrop = kit::render_rigid(nothing(), resting, camera, width, height);
  const kit::Pinhole view(camera, width, height);
  const auto centre = view.project(0, 0.1, 0);
  REQUIRE(centre);
  CHECK(body_coloured(image.pixel(int(centre->px), int(centre->py)), kit::rigid_part_colour(0)));
  CHECK(!body_coloured(backdrop.pixel(int(centre->px), int(centre->py)), kit::rigid_part_colour(0)));
  // Outside the rectangle the body's corners project into, the backdrop, at most darkened by
  // the body's shadow (which must be somewhere).
  double left = width, right = 0, top = height, bottom = 0;
  for (const Vec3& corner : world_corners(box.parts[0], resting)) {
    const auto p = view.project(corner.x(), corner.y(), corner.z());
    REQUIRE(p);
    left = std::min(left, p->px), right = std::max(right, p->px);
    top = std::min(top, p->py), bottom = std::max(bottom, p->py);
  }
  CHECK(right - left > 20);  // a readable body: tens of pixels across
  long outside = 0, same = 0, shadowed = 0;
  for (int py = 0; py < height; ++py)
    for (int px = 0; px < width; ++px) {
      if (px + 1 >= left && px <= right && py + 1 >= top && py <= bottom) continue;
      ++outside;
      const float *drawn = image.pixel(px, py), *behind = backdrop.pixel(px, py);
      bool darker = false, equal = true;
      for (int k = 0; k < 3; ++k) {
        CHECK(drawn[k] <= behind[k] + 1e-7f);
        darker = darker || drawn[k] < behind[k] - 1e-3f;
        equal = equal && drawn[k] == behind[k];
      }
      same += equal, shadowed += darker;
    }
  CHECK(double(same) > 0.9 * double(outside));
  CHECK(shadowed > 0);
  // The backdrop: sky at the top (bluer than the horizon), the ground at the bottom.
  CHECK(backdrop.pixel(0, 0)[2] > backdrop.pixel(0, 0)[0]);
  CHECK(std::abs(backdrop.pixel(width / 2, height - 1)[0] - kit::cloth_sky_bottom[0]) > 0.02);
}

TEST_CASE("a turned body renders differently; the T-handle's bar and stem show their own colours",
          "[rigid][render]") {
  const kit::RigidShape box = kit::box_shape(1.0, {0.4, 0.2, 0.3});
  const kit::RigidState upright = placed({0, 0.5, 0}, Mat3::Identity());
  const kit::RigidState tilted = placed({0, 0.5, 0}, turned(0.5, {1, 1, 0}));
  const kit::Camera camera = kit::rigid_camera(box, {upright}, true);
  const kit::Image a = kit::render_rigid(box, upright, camera, 120, 90);
  const kit::Image b = kit::render_rigid(box, tilted, camera, 120, 90);
  CHECK(pixels_differing(a, b) > 200);

  const kit::RigidShape handle = kit::t_handle_shape(0.5);
  const kit::RigidState spinning = placed({0, 1, 0}, turned(0.3, {0, 1, 0}));
  const kit::Image t =
      kit::render_rigid(handle, spinning, kit::rigid_camera(handle, {spinning}, false), 120, 90);
  long bar = 0, stem = 0;
  for (int py = 0; py < t.height; ++py)
    for (int px = 0; px < t.width; ++px) {
      bar += body_coloured(t.pixel(px, py), kit::rigid_part_colour(0));
      stem += body_coloured(t.pixel(px, py), kit::rigid_part_colour(1));
    }
  CHECK(bar > 100);
  CHECK(stem > 100);
}

TEST_CASE("the default camera keeps a falling box and a spinning T-handle in the picture",
          "[rigid][render]") {
  const int width = 160, height = 120;
  auto all_in_view = [&](const kit::RigidShape& shape, const std::vector<kit::RigidState>& frames,
                         bool ground) {
    const kit::Pinhole view(kit::rigid_camera(shape, frames, ground, double(width) / height), width, height);
    bool inside = true;
    for (const kit::RigidState& state : frames)
      for (const kit::BoxPart& part : shape.parts)
        for (const Vec3& corner : world_corners(part, state)) {
          const auto p = view.project(corner.x(), corner.y(), corner.z());
          inside = inside && p && p->px >= 0 && p->px <= width && p->py >= 0 && p->py <= height;
        }
    return inside;
  };
  const kit::RigidShape box = kit::box_shape(1.0, {0.4, 0.2, 0.3});
  std::vector<kit::RigidState> falling;
  for (int k = 0; k <= 10; ++k)
    falling.push_back(placed({0.02 * k, 1.0 - 0.09 * k, 0}, turned(0.3 * k, {1, 0, 1})));
  CHECK(all_in_view(box, falling, true));
  const kit::RigidShape handle = kit::t_handle_shape(0.5);
  std::vector<kit::RigidState> spinning;
  for (int k = 0; k < 8; ++k) spinning.push_back(placed({0, 1, 0}, turned(0.8 * k, {1, 0.1, 0.2})));
  CHECK(all_in_view(handle, spinning, false));
  CHECK_THROWS_AS(kit::rigid_camera(box, {}, true), std::invalid_argument);
}

TEST_CASE("write_rigid_output writes a frame and a mesh per state, clears stale ones, leaves no temporary",
          "[rigid][render]") {
  const kit::test::TempDir dir("rigid-output");
  const kit::RigidShape box = kit::box_shape(1.0, {0.4, 0.2, 0.3});
  std::vector<kit::RigidState> frames;
  for (int k = 0; k < 3; ++k) frames.push_back(placed({0, 1.0 - 0.4 * k, 0}, turned(0.4 * k, {0, 0, 1})));
  // An earlier, longer run's frame and mesh go; another body's mesh stays.
  std::filesystem::create_directories(dir.path() / "drop_frames");
  std::filesystem::create_directories(dir.path() / "drop_meshes");
  kit::write_png(kit::Image(8, 6, {0, 0, 0}), dir.path() / "drop_frames" / "frame_0007.png");
  kit::write_rigid_obj(dir.path() / "drop_meshes" / "drop_0007.obj", box, frames[0]);
  kit::write_rigid_obj(dir.path() / "drop_meshes" / "other_0001.obj", box, frames[0]);
  kit::RigidOutputOptions options;
  options.dir = dir.path(), options.width = 64, options.height = 48, options.fps = 10, options.stem = "drop";
  const kit::RigidOutput out =
      kit::write_rigid_output(box, frames, kit::rigid_camera(box, frames, true), options);
  REQUIRE(out.frames.size() == 3);
  REQUIRE(out.meshes.size() == 3);
  CHECK(out.frames[2] == dir.path() / "drop_frames" / "frame_0002.png");
  CHECK(out.meshes[2] == dir.path() / "drop_meshes" / "drop_0002.obj");
  for (const auto& frame : out.frames) CHECK(kit::read_png(frame).width == 64);
  for (const auto& mesh : out.meshes) CHECK(kit::read_obj(mesh).faces.size() == 12);
  CHECK(kit::test::files_under(dir.path() / "drop_frames").size() == 3);
  CHECK(kit::test::files_under(dir.path() / "drop_meshes").size() == 4);  // and other_0001.obj
  CHECK(std::filesystem::exists(dir.path() / "drop_meshes" / "other_0001.obj"));
  CHECK(out.sheet == dir.path() / "drop_sheet.png");
  CHECK(std::filesystem::exists(out.sheet));
  CHECK(out.player == dir.path() / "drop_play.gp");
  CHECK(std::filesystem::exists(out.player));
  if (kit::find_ffmpeg().empty()) {
    CHECK(out.movies.empty());
    CHECK(!out.note.empty());
  } else {
    CHECK(out.movies.size() == 2);
  }
  for (const auto& movie : out.movies) CHECK(std::filesystem::exists(movie));
  for (const auto& file : kit::test::files_under(dir.path()))
    CHECK(file.filename().string().find(".tmp") == std::string::npos);
  // No state: the stale files go, and nothing is written.
  const kit::RigidOutput none =
      kit::write_rigid_output(box, {}, kit::rigid_camera(box, frames, true), options);
  CHECK(none.frames.empty());
  CHECK(!none.note.empty());
  CHECK(kit::test::files_under(dir.path() / "drop_frames").empty());
  CHECK(kit::test::files_under(dir.path() / "drop_meshes").size() == 1);  // other_0001.obj
  // No folder: nothing at all.
  const kit::test::TempDir empty("rigid-output-none");
  options.dir.clear();
  CHECK(kit::write_rigid_output(box, frames, kit::rigid_camera(box, frames, true), options).frames.empty());
  CHECK(kit::test::files_under(empty.path()).empty());
}
