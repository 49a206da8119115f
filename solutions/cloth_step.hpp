#pragma once
// Ex 6.3: one step of the lecture's cloth loop, with pins (lecture, "Algorithme Euler explicite"):
//   F = forces(x, v);   v_i += Δt F_i / m_i;   x_i += Δt v_i      (the NEW velocity)
// ERRATA item 7: updating x with the new v makes this symplectic (semi-implicit) Euler, not the
// explicit Euler of chapter 1, and the lecture's loop drops 1/m (it assumes m = 1): here each node
// divides by its own mass. A pinned node does not move: its velocity stays zero and its position
// stays where it is, whatever force acts on it.
#include <cstdint>
#include <vector>

#include <kit/base/not_implemented.hpp>
#include <kit/cloth/cloth.hpp>

namespace kit {

/// Advances positions x [m] and velocities v [m/s] (row i = node i) by dt [s]. `forces(x, v, f)`
/// fills f [N] with the total force on every node; call it once. masses [kg] per node; `pins` the
/// indices of the nodes held still. f is scratch space of the same shape as x (no allocation).
template <class Forces>
void symplectic_cloth_step(NodeArray& x, NodeArray& v, const Eigen::VectorXd& masses,
                           const std::vector<std::int32_t>& pins, const Forces& forces, NodeArray& f,
                           double dt) {
  // BEGIN SOLUTION ex 6.3: f from forces(x, v, f); v += dt f/m row by row; pinned rows of v back to zero; then x += dt v
  forces(x, v, f);
  for (int axis = 0; axis < 3; ++axis) v.col(axis).array() += dt * f.col(axis).array() / masses.array();
  for (std::int32_t pin : pins) v.row(pin).setZero();
  x += dt * v;
  // END SOLUTION
}

}  // namespace kit
