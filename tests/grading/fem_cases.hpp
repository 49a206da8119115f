#pragma once
// Random elements shared by chapter 9's graded tests: a well-shaped rest triangle of any size and
// orientation in the plane, a deformation of it in space (a rotation, a stretch, a shear and a
// translation), and Lamé's parameters over four decades, all from the seeded generator of
// cases.hpp. Also the element's forces by central differences of its energy, the truth
// the forces are graded against.
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include <Eigen/Geometry>

#include <kit/fem/fem_element.hpp>

#include "cases.hpp"

namespace kit::test {

struct RandomElement {
  std::array<Eigen::Vector2d, 3> rest_nodes;  ///< X0, X1, X2 [m], counter-clockwise
  RestTriangle rest;
  std::array<Vec3, 3> nodes;  ///< x0, x1, x2 [m]
  Matrix32 F;                 ///< the deformation gradient they were made with
  Lame lame;                  ///< [Pa]
};

/// A rotation of space drawn uniformly.
inline Eigen::Matrix3d random_space_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const double w = normal(rng), x = normal(rng), y = normal(rng), z = normal(rng);
  return Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
}

/// An element whose rest triangle has sides 10^[−2, 0] m and angles over 30°, thickness 1 mm to
/// 1 cm, deformed by F = R [I + strain] with `strain` a random symmetric 2×2 of entries up to
/// `strain_size` (kept below 1, so the element is never turned inside out).
inline RandomElement random_element(std::mt19937_64& rng, double strain_size = 0.3) {
  RandomElement e;
  const double size = std::pow(10.0, uniform(rng, -2, 0));
  const double turn = uniform(rng, 0, 2 * M_PI);
  const Eigen::Vector2d origin(uniform(rng, -1, 1), uniform(rng, -1, 1));
  // An equilateral triangle with each corner moved by up to 15% of the side, then turned.
  const Eigen::Rotation2Dd in_plane(turn);
  for (int i = 0; i < 3; ++i) {
    const double corner = 2 * M_PI * i / 3;
    const Eigen::Vector2d jitter(uniform(rng, -0.15, 0.15), uniform(rng, -0.15, 0.15));
    e.rest_nodes[i] =
        origin + size * (in_plane * (Eigen::Vector2d(std::cos(corner), std::sin(corner)) + jitter));
  }
  e.rest =
      rest_triangle(e.rest_nodes[0], e.rest_nodes[1], e.rest_nodes[2], std::pow(10.0, uniform(rng, -3, -2)));
  Matrix2 strain;
  strain(0, 0) = uniform(rng, -strain_size, strain_size);
  strain(1, 1) = uniform(rng, -strain_size, strain_size);
  strain(0, 1) = strain(1, 0) = uniform(rng, -strain_size, strain_size) / 2;
  const Eigen::Matrix3d R = random_space_rotation(rng);
  e.F = R.leftCols<2>() * (Matrix2::Identity() + strain);
  const Vec3 shift(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  for (int i = 0; i < 3; ++i) e.nodes[i] = e.F * e.rest_nodes[i] + shift;
  const double young = std::pow(10.0, uniform(rng, 4, 8));
  const double poisson = uniform(rng, 0, 0.45);
  e.lame = {young * poisson / (1 - poisson * poisson), young / (2 * (1 + poisson))};
  return e;
}

inline std::string describe(const RandomElement& e) {
  std::ostringstream s;
  s << "rest nodes (" << e.rest_nodes[0].transpose() << ") (" << e.rest_nodes[1].transpose() << ") ("
    << e.rest_nodes[2].transpose() << ") m, V = " << e.rest.volume << " m³\nF =\n"
    << e.F << "\nlambda = " << e.lame.lambda << " Pa, mu = " << e.lame.mu << " Pa";
  return s.str();
}

/// The element's F from its nodes, written out here so that no graded test needs ex 9.1.
inline Matrix32 gradient_of(const std::array<Vec3, 3>& x, const Matrix2& rest_inverse) {
  Matrix32 edges;
  edges.col(0) = x[1] - x[0];
  edges.col(1) = x[2] - x[0];
  return edges * rest_inverse;
}

/// The element's St Venant–Kirchhoff energy V (μ E:E + ½λ tr(E)²) [J] with its nodes at x.
inline double energy_at(const std::array<Vec3, 3>& x, const RandomElement& e) {
  const Matrix32 F = gradient_of(x, e.rest.inverse);
  const Matrix2 right_cauchy_green = F.transpose() * F;
  const Matrix2 E = (right_cauchy_green - Matrix2::Identity()) / 2;
  return e.rest.volume * (e.lame.mu * E.squaredNorm() + 0.5 * e.lame.lambda * E.trace() * E.trace());
}

/// −∂W/∂x by central differences of the energy, each coordinate moved by ±δ with δ = 1e-6 of
/// the element's size: a truncation error of order δ² and a round-off of order ε W / δ.
inline ElementForces forces_by_differences(const RandomElement& e) {
  const double size = (e.rest_nodes[1] - e.rest_nodes[0]).norm();
  const double delta = 1e-6 * size;
  ElementForces f;
  for (int node = 0; node < 3; ++node)
    for (int axis = 0; axis < 3; ++axis) {
      auto plus = e.nodes, minus = e.nodes;
      plus[node][axis] += delta;
      minus[node][axis] -= delta;
      f(axis, node) = -(energy_at(plus, e) - energy_at(minus, e)) / (2 * delta);
    }
  return f;
}

}  // namespace kit::test
