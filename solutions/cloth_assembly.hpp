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
  // BEGIN SOLUTION ex 7.2: triplets: m(1 + h c) on each diagonal; per spring B = h μ x̂x̂ᵀ − h² J at (a,a), (b,b), −B at (a,b), (b,a); b = h f + h² Σ ±J (v_a − v_b)
  const Eigen::Index n = in.x.rows();
  const double h = in.h;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(3 * n + 36 * in.springs.size()));
  b.resize(3 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double diagonal = in.masses[i] * (1 + h * in.drag.value_or(0.0));
    for (int k = 0; k < 3; ++k) entries.emplace_back(3 * i + k, 3 * i + k, diagonal);
    b.segment<3>(3 * i) = h * in.f.row(i).transpose();
  }
  const auto put = [&](Eigen::Index row_node, Eigen::Index col_node, const Mat3& block) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) entries.emplace_back(3 * row_node + r, 3 * col_node + c, block(r, c));
  };
  for (std::size_t s = 0; s < in.springs.size(); ++s) {
    const Eigen::Index sa = in.springs.a[s], sb = in.springs.b[s];
    const Mat3& J = in.stiffness[s];
    Mat3 block = -h * h * J;
    const Vec3 gap = in.x.row(sa) - in.x.row(sb);
    if (gap.norm() > 0) {
      const Vec3 unit = gap.normalized();
      block += h * in.springs.damping[s] * unit * unit.transpose();
    }
    put(sa, sa, block);
    put(sb, sb, block);
    put(sa, sb, -block);
    put(sb, sa, -block);
    const Vec3 pull = h * h * J * (in.v.row(sa) - in.v.row(sb)).transpose();
    b.segment<3>(3 * sa) += pull;
    b.segment<3>(3 * sb) -= pull;
  }
  A.resize(3 * n, 3 * n);
  A.setFromTriplets(entries.begin(), entries.end());
  // END SOLUTION
}

}  // namespace kit
