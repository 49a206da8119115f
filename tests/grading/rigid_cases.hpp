#pragma once
// Random inputs shared by chapter 8's graded tests: vectors, rotations, unit quaternions and the
// general matrices explicit Euler's R becomes, all from the seeded generator of cases.hpp.
#include <random>

#include <Eigen/Geometry>

#include <kit/rigid/rigid_body.hpp>

#include "cases.hpp"

namespace kit::test {

/// Each component uniform in [−scale, scale].
inline Vec3 random_vector(std::mt19937_64& rng, double scale) {
  const double x = uniform(rng, -scale, scale);
  const double y = uniform(rng, -scale, scale);
  const double z = uniform(rng, -scale, scale);
  return {x, y, z};
}

/// A unit quaternion drawn uniformly: four normal numbers, normalised.
inline Quat random_unit_quaternion(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const double w = normal(rng), x = normal(rng), y = normal(rng), z = normal(rng);
  return Quat(w, x, y, z).normalized();
}

/// A rotation drawn uniformly (random_unit_quaternion's matrix).
inline Mat3 random_rotation(std::mt19937_64& rng) { return random_unit_quaternion(rng).toRotationMatrix(); }

/// Any 3×3 matrix, entries in [−2, 2]: what explicit Euler's R is once it has left the rotations.
inline Mat3 random_matrix(std::mt19937_64& rng) {
  Mat3 m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = uniform(rng, -2, 2);
  return m;
}

inline double largest_entry(const Mat3& m) { return m.cwiseAbs().maxCoeff(); }

}  // namespace kit::test
