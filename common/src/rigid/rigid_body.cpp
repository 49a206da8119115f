#include <kit/rigid/rigid_body.hpp>

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <Eigen/SVD>

namespace kit {
namespace {

// The inertia of a solid box about its own centre, its axes along the body axes [kg·m²].
Mat3 box_inertia(double mass, const Vec3& sides) {
  const Vec3 squared = sides.cwiseAbs2();
  return (mass / 12.0 * Vec3(squared.y() + squared.z(), squared.x() + squared.z(), squared.x() + squared.y()))
      .asDiagonal();
}

// The parallel-axis theorem: the inertia of a part of mass m about a point `offset` away from its
// own centre, I + m (|d|² 1 − d dᵀ) [kg·m²].
Mat3 moved_inertia(const Mat3& own, double mass, const Vec3& offset) {
  return own + mass * (offset.squaredNorm() * Mat3::Identity() - offset * offset.transpose());
}

// The eight corners of a box part [m].
void add_corners(std::vector<Vec3>& corners, const BoxPart& part) {
  for (int i = 0; i < 8; ++i) {
    const Vec3 sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    corners.push_back(part.centre + 0.5 * sign.cwiseProduct(part.sides));
  }
}

void require_positive(const char* what, double value) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(fmt::format("{} must be a positive finite number, not {}", what, value));
}

}  // namespace

Vec3 RigidShape::principal_moments() const {
  Eigen::SelfAdjointEigenSolver<Mat3> solver(inertia, Eigen::EigenvaluesOnly);
  return solver.eigenvalues();  // ascending
}

RigidShape box_shape(double mass, const Vec3& sides) {
  require_positive("a box's mass [kg]", mass);
  for (int k = 0; k < 3; ++k) require_positive("a box's side [m]", sides[k]);
  RigidShape shape{"box", mass, box_inertia(mass, sides), {}, {{Vec3::Zero(), sides}}, {}};
  add_corners(shape.corners, shape.parts.front());
  shape.inverse_inertia = shape.inertia.inverse();
  return shape;
}

RigidShape cylinder_shape(double mass, double radius, double height) {
  require_positive("a cylinder's mass [kg]", mass);
  require_positive("a cylinder's radius [m]", radius);
  require_positive("a cylinder's height [m]", height);
  const double side = (3 * radius * radius + height * height) / 12.0 * mass;
  RigidShape shape{"cylinder",
                   mass,
                   Vec3(side, mass * radius * radius / 2, side).asDiagonal(),
                   {},
                   {{Vec3::Zero(), Vec3(2 * radius, height, 2 * radius)}},
                   {}};
  constexpr int rim = 16;  // the corners of a 16-sided prism: the rims at y = ±h/2
  for (int k = 0; k < rim; ++k) {
    const double angle = 2 * M_PI * k / rim;
    for (double y : {-height / 2, height / 2})
      shape.corners.emplace_back(radius * std::cos(angle), y, radius * std::sin(angle));
  }
  shape.inverse_inertia = shape.inertia.inverse();
  return shape;
}

RigidShape t_handle_shape(double mass) {
  require_positive("the T-handle's mass [kg]", mass);
  const Vec3 bar_sides(0.30, 0.04, 0.04), stem_sides(0.04, 0.30, 0.04);
  const double bar_volume = bar_sides.prod(), stem_volume = stem_sides.prod();
  const double bar_mass = mass * bar_volume / (bar_volume + stem_volume), stem_mass = mass - bar_mass;
  // The bar's centre at the origin, the stem hanging below it; then both moved so that the
  // centre of mass is the origin of the body frame.
  const Vec3 bar_centre = Vec3::Zero(), stem_centre(0, -(bar_sides.y() + stem_sides.y()) / 2, 0);
  const Vec3 centre_of_mass = (bar_mass * bar_centre + stem_mass * stem_centre) / mass;
  RigidShape shape{"t-handle",
                   mass,
                   Mat3::Zero(),
                   {},
                   {{bar_centre - centre_of_mass, bar_sides}, {stem_centre - centre_of_mass, stem_sides}},
                   {}};
  shape.inertia = moved_inertia(box_inertia(bar_mass, bar_sides), bar_mass, shape.parts[0].centre) +
                  moved_inertia(box_inertia(stem_mass, stem_sides), stem_mass, shape.parts[1].centre);
  for (const auto& part : shape.parts) add_corners(shape.corners, part);
  shape.inverse_inertia = shape.inertia.inverse();
  return shape;
}

namespace {

// The bodies of chapter 8 by name: the one table --body, its help and shape_named read.
struct NamedShape {
  const char* name;
  RigidShape (*make)();
};
const NamedShape named_shapes[] = {
    {"t-handle", [] { return t_handle_shape(0.5); }},
    {"box", [] { return box_shape(1.0, Vec3(0.4, 0.2, 0.3)); }},
    {"cylinder", [] { return cylinder_shape(1.0, 0.1, 0.4); }},
};

}  // namespace

std::vector<std::string> shape_names() {
  std::vector<std::string> names;
  for (const auto& shape : named_shapes) names.emplace_back(shape.name);
  return names;
}

RigidShape shape_named(const std::string& name) {
  for (const auto& shape : named_shapes)
    if (name == shape.name) return shape.make();
  throw std::invalid_argument(fmt::format("body '{}': expected {}", name, fmt::join(shape_names(), ", ")));
}

RigidState spinning_state(const RigidShape& shape, const Vec3& x, const Vec3& omega_body) {
  RigidState state;
  state.x = x;
  state.L = shape.inertia * omega_body;  // R = 1: the body and world frames coincide
  return state;
}

Vec3 body_momentum(const RigidState& state) { return state.R.transpose() * state.L; }

double rotational_energy(const RigidShape& shape, const RigidState& state) {
  const Vec3 body = body_momentum(state);
  return 0.5 * body.dot(shape.inverse_inertia * body);
}

double kinetic_energy(const RigidShape& shape, const RigidState& state) {
  return state.P.squaredNorm() / (2 * shape.mass) + rotational_energy(shape, state);
}

double orthonormality_error(const Mat3& R) { return (R.transpose() * R - Mat3::Identity()).norm(); }

Mat3 nearest_rotation(const Mat3& R) {
  Eigen::JacobiSVD<Mat3> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 U = svd.matrixU();
  if ((U * svd.matrixV().transpose()).determinant() < 0)
    U.col(2) *= -1;  // a reflection: flip the weakest axis
  return U * svd.matrixV().transpose();
}

}  // namespace kit
