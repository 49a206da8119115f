#pragma once
// Ex 7.3: Baraff & Witkin's modified preconditioned conjugate gradient (1998, §5.3), the solver
// of the implicit cloth step. Each node i has a 3×3 filter S_i: the directions it may move in
// (S = I free, S = 0 pinned, S = I − nnᵀ held on a plane of normal n). The method runs CG on
// S A S restricted to those directions, so constraints hold exactly inside the solve:
//   x = 0;  r = S b;  c = S P⁻¹ r;  δ = rᵀ P⁻¹ r ... as in the paper, with P = diag(A):
//   q = S (A c);  α = δ / (cᵀ q);  x += α c;  r −= α q;  s = P⁻¹ r;  δ' = rᵀ s;  c = S (s + (δ'/δ) c).
// CG needs a positive definite matrix: if cᵀ q ≤ 0 it must stop and say so, never divide by it.
// It stops when ‖r‖ ≤ tolerance ‖S b‖ (r is already filtered) or after max_iterations products.
#include <cmath>
#include <vector>

#include <kit/base/not_implemented.hpp>
#include <kit/cloth/cloth_implicit_kernels.hpp>

namespace kit {

/// Solves A x = b under the per-node filters; see PcgResult for what it reports.
inline PcgResult filtered_pcg(const SparseMatrix& A, const Eigen::VectorXd& b,
                              const std::vector<Mat3>& filters, double tolerance, int max_iterations) {
  // BEGIN SOLUTION ex 7.3: filter = S_i on each node's 3 entries; P⁻¹ = 1/diag(A); loop while ‖r‖ > tol ‖S b‖; stop on cᵀq ≤ 0
  const auto filtered = [&](Eigen::VectorXd w) {
    for (std::size_t i = 0; i < filters.size(); ++i) {
      const Eigen::Index k = 3 * Eigen::Index(i);
      w.segment<3>(k) = filters[i] * w.segment<3>(k);
    }
    return w;
  };
  const Eigen::VectorXd inverse_diagonal = A.diagonal().cwiseInverse();
  PcgResult out;
  out.x = Eigen::VectorXd::Zero(b.size());
  Eigen::VectorXd r = filtered(b);
  const double target = tolerance * r.norm();
  Eigen::VectorXd c = filtered(inverse_diagonal.cwiseProduct(r));
  double delta = r.dot(c);
  double r_norm = r.norm();
  while (r_norm > target && out.iterations < max_iterations) {
    const Eigen::VectorXd q = filtered(A * c);
    ++out.iterations;
    const double curvature = c.dot(q);
    if (!(curvature > 0)) {
      out.negative_curvature = true;
      break;
    }
    const double alpha = delta / curvature;
    out.x += alpha * c;
    r -= alpha * q;
    const Eigen::VectorXd s = inverse_diagonal.cwiseProduct(r);
    const double next = r.dot(s);
    c = filtered(s + (next / delta) * c);
    delta = next;
    r_norm = r.norm();
  }
  const double start = filtered(b).norm();
  out.residual = start > 0 ? r_norm / start : 0.0;
  out.converged = !out.negative_curvature && r_norm <= target;
  return out;
  // END SOLUTION
}

}  // namespace kit
