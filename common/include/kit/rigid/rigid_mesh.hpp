#pragma once
// A rigid body's surface in the world (chapter 8): the six faces of each of its box parts, moved
// to where the body is. What the rigid renderer draws and the rigid OBJ writer writes.
#include <array>
#include <cstddef>
#include <vector>

#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// One flat face of a box part, in the world.
struct RigidFace {
  std::array<Vec3, 4> corners;  ///< [m], counter-clockwise seen from outside the box
  Vec3 normal = Vec3::UnitY();  ///< outward, unit
  std::size_t part = 0;         ///< the index in RigidShape::parts of the box it bounds
};

/// The faces of every part of `shape` with the body at `state`: 6 per part, part by part, each
/// part's in the order −x, +x, −y, +y, −z, +z of the body frame. A point c of the body frame is
/// at x + R c in the world. The normal is that of the corners' plane, (c1 − c0) × (c3 − c0)
/// normalised: outward for a rotation R (and any R of positive determinant, such as explicit
/// Euler's drifted one); R n_body normalised where that product vanishes (a singular R).
std::vector<RigidFace> rigid_faces(const RigidShape& shape, const RigidState& state);

}  // namespace kit
