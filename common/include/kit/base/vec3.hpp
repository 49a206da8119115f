#pragma once
// The kit's words for 3-D geometry: a point, direction, velocity or force in the world (Vec3; y
// is up, units as its use says: [m], [m/s], [N]) and a 3×3 matrix (Mat3: a rotation, an inertia
// tensor, a block of a stiffness matrix). Every model says these two, so a vector passes from
// the cloth to the renderer or from a rigid body to the camera without a conversion. Colours are
// not vectors: they are kit::Colour (render/image.hpp).
//
// Sums such as a dot product are written out where their last bit matters (the renderers, the
// emitters): Eigen's a.dot(b) adds a0·b0 + (a1·b1 + a2·b2), the kit's formulas add left to right.
#include <Eigen/Core>

namespace kit {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

}  // namespace kit
