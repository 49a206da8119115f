#pragma once
// Ex 6.4: a node that ends a step inside a fixed sphere is put back on its surface, and its
// velocity answers the contact (lecture, "Vêtement = Tissu + collisions"):
//   - position: projected radially onto the surface, x ← c + r n with n = (x − c)/|x − c|;
//   - normal velocity: an inward one (v·n < 0) is removed (an inelastic contact), v_n ← 0;
//   - friction (Coulomb): the tangential velocity loses μ times the normal speed removed,
//     |Δv_t| = min(|v_t|, μ |v·n|); it stops when that is all of it (static friction).
// A node already outside, or moving outward, keeps its velocity.
#include <kit/base/not_implemented.hpp>
#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_scene.hpp>

namespace kit {

/// Resolves every node of x [m] (velocities v [m/s]) that lies strictly inside `sphere`.
/// A node exactly at the centre has no radial direction: push it out along +y. Returns the
/// number of nodes that were inside.
inline long collide_sphere(NodeArray& x, NodeArray& v, const SphereCollider& sphere) {
  long inside = 0;
  // BEGIN SOLUTION ex 6.4: for each node with |x − c| < r: n = (x − c)/|x − c| (or +y at c), x = c + r n; if v·n < 0 remove it and shrink v_t by μ|v·n|
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const Vec3 offset = x.row(i).transpose() - sphere.center;
    const double distance = offset.norm();
    if (!(distance < sphere.radius)) continue;
    ++inside;
    const Vec3 n = distance > 0 ? Vec3(offset / distance) : Vec3(0, 1, 0);
    x.row(i) = (sphere.center + sphere.radius * n).transpose();
    const Vec3 vel = v.row(i).transpose();
    const double vn = vel.dot(n);
    if (vn >= 0) continue;
    const Vec3 tangential = vel - vn * n;
    const double speed = tangential.norm(), loss = sphere.friction * -vn;
    v.row(i) = (speed > loss ? Vec3(tangential * (1 - loss / speed)) : Vec3::Zero()).transpose();
  }
  // END SOLUTION
  return inside;
}

}  // namespace kit
