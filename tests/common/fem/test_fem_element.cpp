// Chapter 9's element as the kit keeps it (the rest shape, the small-strain model), Richardson's
// estimate, and the mesh's boundary loop.
#include <cmath>

#include <kit_catch.hpp>

#include <kit/fem/fem_element.hpp>
#include <kit/fem/fem_mesh.hpp>
#include <kit/ode/richardson.hpp>

#include "fem_output.hpp"

TEST_CASE("fem element: the rest shape's Dm⁻¹ and volume; degenerate and clockwise triangles refused",
          "[fem]") {
  const kit::RestTriangle rest = kit::rest_triangle({1, 1}, {3, 1}, {1, 5}, 0.01);
  kit::Matrix2 edges;
  edges << 2, 0, 0, 4;
  CHECK((rest.inverse * edges - kit::Matrix2::Identity()).norm() < 1e-15);
  CHECK(rest.volume == Approx(0.5 * 2 * 4 * 0.01).epsilon(1e-15));
  CHECK_THROWS_AS(kit::rest_triangle({0, 0}, {0, 1}, {1, 0}, 0.01), std::invalid_argument);  // clockwise
  CHECK_THROWS_AS(kit::rest_triangle({0, 0}, {1, 0}, {2, 0}, 0.01), std::invalid_argument);  // on a line
  CHECK_THROWS_AS(kit::rest_triangle({0, 0}, {1, 0}, {0, 1}, 0), std::invalid_argument);
  CHECK_THROWS_AS(kit::rest_triangle({0, 0}, {1, 0}, {0, 1}, NAN), std::invalid_argument);
}

TEST_CASE("fem element: the small strain reads a turn as (cos θ − 1) I; its forces and stiffness agree",
          "[fem]") {
  const kit::RestTriangle rest = kit::rest_triangle({0, 0}, {0.1, 0}, {0, 0.1}, 0.01);
  const kit::Lame lame{3e8, 4e8};
  for (const double theta : {0.1, 1.0, M_PI / 2, 3.0}) {
    kit::Matrix32 F = kit::Matrix32::Zero();
    F.topRows<2>() << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
    INFO("θ = " << theta);
    CHECK((kit::cauchy_strain(F) - (std::cos(theta) - 1) * kit::Matrix2::Identity()).norm() < 1e-15);
    // The model is linear: its forces are −K u for u the nodes' move from rest.
    const kit::Matrix9 K = kit::linear_stiffness(rest.inverse, rest.volume, lame);
    kit::Vector9 u = kit::Vector9::Zero();
    const kit::Matrix2 G = F.topRows<2>() - kit::Matrix2::Identity();
    u.segment<2>(3) = G * Eigen::Vector2d(0.1, 0);
    u.segment<2>(6) = G * Eigen::Vector2d(0, 0.1);
    const kit::ElementForces f = kit::linear_forces(F, rest.inverse, rest.volume, lame);
    CHECK((f.reshaped() - K * u).norm() < 1e-9 * f.norm());
    CHECK(f.rowwise().sum().norm() < 1e-9 * f.norm());
  }
  CHECK(kit::linear_stress(kit::Matrix2::Identity(), lame)
            .isApprox(kit::Matrix2::Identity() * (2 * 3e8 + 2 * 4e8)));
}

TEST_CASE("richardson: a sequence converging as N^−2 gives its limit and order exactly; an oscillation none",
          "[fem]") {
  const auto value = [](double n) { return 3.0 + 5.0 / (n * n); };
  const kit::Convergence c = kit::richardson(value(8), value(16), value(32));
  CHECK(c.converges);
  CHECK(c.order == Approx(2).epsilon(1e-12));
  CHECK(c.limit == Approx(3).epsilon(1e-13));
  CHECK(c.remaining == Approx(5.0 / 1024 / 3).epsilon(1e-9));
  CHECK_FALSE(kit::richardson(1.0, 2.0, 1.5).converges);
  CHECK_FALSE(kit::richardson(1.0, 1.0, 1.0).converges);
}

TEST_CASE("boundary loop: counter-clockwise, every boundary node once, on regular and irregular meshes",
          "[fem]") {
  for (const auto& mesh : {kit::regular_rectangle_mesh(2, 1, 4, 2, kit::CellDiagonal::alternating),
                           kit::irregular_rectangle_mesh(2, 1, 6, 3, 9)}) {
    const std::vector<int> loop = kit::boundary_loop(mesh);
    REQUIRE(loop.size() >= 4);
    CHECK(loop.front() == loop.back());
    double twice_area = 0;  // the shoelace formula: positive when counter-clockwise
    for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
      const auto& a = mesh.nodes[loop[k]];
      const auto& b = mesh.nodes[loop[k + 1]];
      twice_area += a.x() * b.y() - b.x() * a.y();
      CHECK((a.x() == 0 || a.x() == 2 || a.y() == 0 || a.y() == 1));
    }
    CHECK(twice_area / 2 == Approx(2.0).epsilon(1e-12));
    long on_boundary = 0;
    for (const auto& node : mesh.nodes)
      on_boundary += node.x() == 0 || node.x() == 2 || node.y() == 0 || node.y() == 1;
    CHECK(long(loop.size()) - 1 == on_boundary);
  }
}
