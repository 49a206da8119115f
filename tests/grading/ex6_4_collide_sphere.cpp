// ex 6.4: nodes inside a sphere go back to its surface; velocity answers with friction
// (cloth_sphere.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "cloth_sphere.hpp"

namespace {
using kit::Vec3;
kit::NodeArray row(const Vec3& p) {
  kit::NodeArray a(1, 3);
  a.row(0) = p.transpose();
  return a;
}
}  // namespace

TEST_CASE("ex 6.4: a node inside goes to the surface along its radius; nodes outside are untouched",
          "[grade][06-cloth-explicit][ex6.4]") {
  auto rng = kit::test::random_engine();
  const kit::SphereCollider sphere{{0.3, -0.2, 1.0}, 0.8, 0.4};
  kit::NodeArray x(400, 3), v(400, 3);
  for (int i = 0; i < 400; ++i)
    for (int axis = 0; axis < 3; ++axis)
      x(i, axis) = kit::test::uniform(rng, -1.5, 1.5) + sphere.center[axis],
           v(i, axis) = kit::test::uniform(rng, -2, 2);
  const kit::NodeArray x0 = x, v0 = v;
  long inside = 0;
  for (int i = 0; i < 400; ++i) inside += (x0.row(i).transpose() - sphere.center).norm() < sphere.radius;
  CHECK(kit::collide_sphere(x, v, sphere) == inside);
  for (int i = 0; i < 400; ++i) {
    const Vec3 before = x0.row(i).transpose() - sphere.center, after = x.row(i).transpose() - sphere.center;
    if (before.norm() < sphere.radius) {
      CHECK(after.norm() == Approx(sphere.radius).epsilon(1e-12));
      CHECK((after.normalized() - before.normalized()).norm() < 1e-12);  // along its own radius
    } else {
      CHECK(x.row(i) == x0.row(i));
      CHECK(v.row(i) == v0.row(i));
    }
  }
}

TEST_CASE(
    "ex 6.4: an inward velocity loses its normal part, and friction takes μ|v_n| off the tangential part",
    "[grade][06-cloth-explicit][ex6.4]") {
  const Vec3 centre(0, 0, 0);
  const Vec3 inside(0, 0.9, 0);   // under the top of a unit sphere: the normal is +y
  const Vec3 velocity(3, -2, 0);  // v_n = −2, v_t = (3, 0, 0)
  for (double mu : {0.0, 0.5, 1.0, 1.5, 10.0}) {
    kit::NodeArray x = row(inside), v = row(velocity);
    kit::collide_sphere(x, v, {centre, 1.0, mu});
    INFO("mu = " << mu);
    CHECK(x(0, 1) == Approx(1.0).epsilon(1e-14));
    CHECK(std::abs(v(0, 1)) < 1e-14);
    CHECK(v(0, 0) == Approx(std::max(0.0, 3 - 2 * mu)).margin(1e-13));  // |Δv_t| = min(|v_t|, μ|v_n|)
    CHECK(std::abs(v(0, 2)) < 1e-14);
  }
}

TEST_CASE("ex 6.4: a node inside but moving out keeps its velocity", "[grade][06-cloth-explicit][ex6.4]") {
  kit::NodeArray x = row({0.5, 0, 0}), v = row({1, 2, -3});
  CHECK(kit::collide_sphere(x, v, {{0, 0, 0}, 1.0, 2.0}) == 1);
  CHECK(x(0, 0) == Approx(1.0));
  CHECK(v.row(0) == row({1, 2, -3}).row(0));
}

TEST_CASE("ex 6.4: a node at the centre is pushed out along +y", "[grade][06-cloth-explicit][ex6.4]") {
  kit::NodeArray x = row({2, 3, 4}), v = row({0, 0, 0});
  kit::collide_sphere(x, v, {{2, 3, 4}, 0.5, 0.1});
  CHECK(x.allFinite());
  CHECK(x(0, 1) == Approx(3.5));
  CHECK(x(0, 0) == Approx(2.0));
}

TEST_CASE("ex 6.4: the response holds for any normal, not only +y", "[grade][06-cloth-explicit][ex6.4]") {
  auto rng = kit::test::random_engine();
  const kit::SphereCollider sphere{{0.2, -0.4, 0.7}, 1.3, 0.6};
  for (int trial = 0; trial < 200; ++trial) {
    // A direction away from +y and an inward velocity with a tangential part.
    Vec3 n(kit::test::uniform(rng, -1, 1), kit::test::uniform(rng, -1, 0.3), kit::test::uniform(rng, -1, 1));
    n.normalize();
    Vec3 t = n.cross(Vec3(0, 1, 0)).normalized();
    const double vn = -kit::test::uniform(rng, 0.1, 3), vt = kit::test::uniform(rng, 0, 3);
    const Vec3 velocity = vn * n + vt * t;
    kit::NodeArray x = row(sphere.center + kit::test::uniform(rng, 0.1, 0.99) * sphere.radius * n),
                   v = row(velocity);
    kit::collide_sphere(x, v, sphere);
    const Vec3 expected = std::max(0.0, vt - sphere.friction * -vn) * t;
    INFO("trial " << trial << ": n = " << n.transpose() << ", v_n = " << vn << ", v_t = " << vt);
    CHECK((x.row(0).transpose() - (sphere.center + sphere.radius * n)).norm() < 1e-12);
    CHECK((v.row(0).transpose() - expected).norm() < 1e-12);
  }
}
