#pragma once
// Ex 6.1: the force of one cloth spring on its end a (lecture, "Simulation de tissus", in 3-D):
//   F_a = K (L0 − |x|) x/|x|  −  μ ((v_a − v_b)·x̂) x̂,     x = x_a − x_b,  x̂ = x/|x|
// Hooke's law along the spring, plus damping of the rate at which its length changes: only the
// relative velocity ALONG the spring is damped, so a sheet falling as a whole is not slowed. The
// force on b is −F_a (Newton's third law).
#include <kit/base/not_implemented.hpp>
#include <kit/cloth/cloth.hpp>

namespace kit {

/// Force [N] on node a of a spring from a (at xa [m], moving at va [m/s]) to b, with rest length
/// `rest` [m], stiffness family.stiffness [N/m] and damping family.damping [N·s/m]. A spring of
/// zero length has no direction: its force is zero.
inline Vec3 spring_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double rest,
                         const SpringFamily& family) {
  // BEGIN SOLUTION ex 6.1: x = xa − xb, l = |x|; F = [K (L0 − l) − μ (va − vb)·x̂] x̂, and zero when l = 0
  const Vec3 x = xa - xb;
  const double l = x.norm();
  if (l == 0) return Vec3::Zero();
  const Vec3 along = x / l;
  return (family.stiffness * (rest - l) - family.damping * (va - vb).dot(along)) * along;
  // END SOLUTION
}

}  // namespace kit
