#pragma once
// Ex 7.2: the linear system of one implicit cloth step (lecture, "Schéma implicite", in the
// symmetric form of ERRATA item 14, the lecture's A multiplied by M):
//   A = M − h ∂f/∂v − h² ∂f/∂x                                                         [kg]
//   b = h (f_n + h ∂f/∂x v_n)                                                          [kg·m/s]
// Node i owns rows and columns 3i … 3i + 2. For spring s = (a, b), with J = ∂f_a/∂x_a (given)
// and D = ∂f_a/∂v_a = −μ x̂x̂ᵀ (damping along the spring only, x̂ from b to a):
//   B = −h D − h² J  goes to blocks (a, a) and (b, b), and −B to blocks (a, b) and (b, a);
//   ∂f/∂x v_n gains J (v_a − v_b) at node a and −J (v_a − v_b) at node b.
// Each node adds its mass on its diagonal, m (1 + h c) with linear air drag c (∂f/∂v = −m c I).
// Build A from a list of triplets, the straightforward way (duplicates are summed).
#include <vector>

#include <kit/base/not_implemented.hpp>
#include <kit/cloth/cloth_implicit_kernels.hpp>

namespace kit {

/// A (3n×3n, both triangles) and b (3n) of the implicit step from the state in `in`.
inline void assemble_implicit_system(const ImplicitSystemInput& in, SparseMatrix& A, Eigen::VectorXd& b) {
  // TODO(ex 7.2): triplets: m(1 + h c) on each diagonal; per spring B = h μ x̂x̂ᵀ − h² J at (a,a), (b,b), −B at (a,b), (b,a); b = h f + h² Σ ±J (v_a − v_b)
  throw kit::NotImplemented("ex 7.2", "cloth_assembly.hpp");
}

}  // namespace kit
