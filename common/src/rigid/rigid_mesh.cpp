// A rigid body's surface in the world (rigid_mesh.hpp).
#include <kit/rigid/rigid_mesh.hpp>

#include <utility>

namespace kit {

std::vector<RigidFace> rigid_faces(const RigidShape& shape, const RigidState& state) {
  std::vector<RigidFace> faces;
  faces.reserve(6 * shape.parts.size());
  for (std::size_t index = 0; index < shape.parts.size(); ++index) {
    const BoxPart& part = shape.parts[index];
    const Vec3 half = 0.5 * part.sides;
    for (int axis = 0; axis < 3; ++axis)
      for (const double sign : {-1.0, 1.0}) {
        // e_{k+1} × e_{k+2} = e_k: corners going from u towards v turn counter-clockwise about
        // +e_k, so the −e_k face swaps them.
        Vec3 u = Vec3::Unit((axis + 1) % 3), v = Vec3::Unit((axis + 2) % 3);
        if (sign < 0) std::swap(u, v);
        const Vec3 outward = sign * Vec3::Unit(axis);
        const Vec3 face_centre = part.centre + half.cwiseProduct(outward);
        RigidFace face;
        face.part = index;
        const double steps[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int k = 0; k < 4; ++k)
          face.corners[std::size_t(k)] =
              state.x + state.R * (face_centre + half.cwiseProduct(steps[k][0] * u + steps[k][1] * v));
        const Vec3 normal = (face.corners[1] - face.corners[0]).cross(face.corners[3] - face.corners[0]);
        const double length = normal.norm();
        face.normal = length > 0 ? Vec3(normal / length) : Vec3((state.R * outward).normalized());
        faces.push_back(face);
      }
  }
  return faces;
}

}  // namespace kit
