// ex 6.3: one symplectic cloth step with pins (cloth_step.hpp).
#include <cmath>
#include <vector>

#include <kit_catch.hpp>

#include "cases.hpp"
#include "cloth_step.hpp"

namespace {
// A force field written here: each node pulled to the origin by its own spring k_i and pushed
// by a constant wind, F_i = −k_i x_i + w [N]. It counts its calls.
struct TestForces {
  Eigen::VectorXd k;
  kit::Vec3 wind{0.5, -2, 1};
  mutable int calls = 0;
  void operator()(const kit::NodeArray& x, const kit::NodeArray&, kit::NodeArray& f) const {
    ++calls;
    f.resize(x.rows(), 3);
    for (Eigen::Index i = 0; i < x.rows(); ++i) f.row(i) = -k[i] * x.row(i) + wind.transpose();
  }
};
kit::NodeArray random_nodes(std::mt19937_64& rng, long n, double scale) {
  kit::NodeArray a(n, 3);
  for (long i = 0; i < n; ++i)
    for (int axis = 0; axis < 3; ++axis) a(i, axis) = kit::test::uniform(rng, -scale, scale);
  return a;
}
}  // namespace

TEST_CASE("ex 6.3: v += Δt F/m node by node, then x += Δt v with the NEW v; one force call",
          "[grade][06-cloth-explicit][ex6.3]") {
  auto rng = kit::test::random_engine();
  for (int trial = 0; trial < 50; ++trial) {
    const long n = long(kit::test::uniform(rng, 1, 40));
    TestForces forces;
    forces.k = Eigen::VectorXd::NullaryExpr(n, [&] { return kit::test::uniform(rng, 0, 100); });
    const Eigen::VectorXd masses =
        Eigen::VectorXd::NullaryExpr(n, [&] { return kit::test::uniform(rng, 1e-3, 2); });
    kit::NodeArray x = random_nodes(rng, n, 1), v = random_nodes(rng, n, 3), f;
    const kit::NodeArray x0 = x, v0 = v;
    const double dt = kit::test::uniform(rng, 1e-4, 1e-2);
    kit::symplectic_cloth_step(x, v, masses, {}, forces, f, dt);
    CHECK(forces.calls == 1);
    for (long i = 0; i < n; ++i) {
      const kit::Vec3 force = -forces.k[i] * x0.row(i).transpose() + forces.wind;
      const kit::Vec3 v_new = v0.row(i).transpose() + dt * force / masses[i];
      const kit::Vec3 x_new = x0.row(i).transpose() + dt * v_new;
      CHECK((v.row(i).transpose() - v_new).norm() <= 1e-12 * (1 + v_new.norm()));
      CHECK((x.row(i).transpose() - x_new).norm() <= 1e-12 * (1 + x_new.norm()));
    }
  }
}

TEST_CASE("ex 6.3: a pinned node stays where it is, at rest, whatever the force",
          "[grade][06-cloth-explicit][ex6.3]") {
  auto rng = kit::test::random_engine();
  const long n = 12;
  TestForces forces;
  forces.k = Eigen::VectorXd::Constant(n, 50);
  const Eigen::VectorXd masses = Eigen::VectorXd::Constant(n, 0.1);
  kit::NodeArray x = random_nodes(rng, n, 1), v = kit::NodeArray::Zero(n, 3), f;
  const std::vector<std::int32_t> pins{0, 5, 11};
  const kit::NodeArray x0 = x;
  for (int step = 0; step < 100; ++step) kit::symplectic_cloth_step(x, v, masses, pins, forces, f, 1e-3);
  for (auto p : pins) {
    CHECK(x.row(p) == x0.row(p));
    CHECK(v.row(p).norm() == 0);
  }
  CHECK((x.row(1) - x0.row(1)).norm() > 1e-3);  // the free ones moved
}

TEST_CASE("ex 6.3: on a node spring the energy stays bounded below ωΔt = 2 and grows above it",
          "[grade][06-cloth-explicit][ex6.3]") {
  // One node, m = 1 kg, k = 1 N/m (ω = 1 rad/s), no wind: x'' = −x.
  TestForces forces;
  forces.k = Eigen::VectorXd::Constant(1, 1.0), forces.wind.setZero();
  const Eigen::VectorXd masses = Eigen::VectorXd::Ones(1);
  for (double h : {0.5, 1.9, 2.05}) {
    kit::NodeArray x = kit::NodeArray::Zero(1, 3), v = kit::NodeArray::Zero(1, 3), f;
    x(0, 0) = 1;
    double worst = 0;
    for (int step = 0; step < 2000; ++step) {
      kit::symplectic_cloth_step(x, v, masses, {}, forces, f, h);
      worst = std::max(worst, x(0, 0) * x(0, 0) + v(0, 0) * v(0, 0));
    }
    INFO("omega*dt = " << h);
    if (h < 2)
      CHECK(worst <= (2 + h) / (2 - h) * (1 + 1e-9));  // the bound of the modified energy
    else
      CHECK(worst > 1e6);
  }
}
