#include <kit/fem/fem_integrators.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kit {

void explicit_step(FemBody& body, double h, double drag) {
  NodeArray f;
  body.forces(f, drag);
  for (long i = 0; i < body.nodes(); ++i) {
    body.v.row(i) += (h / body.masses[i]) * (body.filters[i] * f.row(i).transpose()).transpose();
    body.x.row(i) += h * body.v.row(i);
  }
}

double explicit_step_limit(const FemBody& body) {
  SparseMatrix K;
  body.stiffness(K);
  const auto is_free = [&](Eigen::Index k) { return body.filters[k / 3](k % 3, k % 3) != 0; };
  double omega_squared = 0;  // Gershgorin: every eigenvalue of M⁻¹K lies within the largest row sum
  for (int row = 0; row < K.outerSize(); ++row) {
    if (!is_free(row)) continue;
    double sum = 0;
    for (SparseMatrix::InnerIterator it(K, row); it; ++it)
      if (is_free(it.col())) sum += std::abs(it.value());
    omega_squared = std::max(omega_squared, sum / body.masses[row / 3]);
  }
  return omega_squared > 0 ? 2 / std::sqrt(omega_squared) : std::numeric_limits<double>::infinity();
}

ImplicitStep implicit_step(FemBody& body, double h, double drag, double tolerance, int max_iterations) {
  SparseMatrix K;
  body.stiffness(K);
  NodeArray f;
  body.forces(f, drag);
  const Eigen::VectorXd v = flatten(body.v);
  SparseMatrix A = (-h * h) * K;  // every diagonal entry is in K's pattern: the node's own block
  for (long i = 0; i < body.nodes(); ++i)
    for (int axis = 0; axis < 3; ++axis)
      A.coeffRef(3 * i + axis, 3 * i + axis) += body.masses[i] * (1 + h * drag);
  Eigen::VectorXd b = h * (flatten(f) + h * (K * v));
  for (long i = 0; i < body.nodes(); ++i) b.segment<3>(3 * i) = body.filters[i] * b.segment<3>(3 * i);
  const PcgResult solve = body.kernels().pcg(A, b, body.filters, tolerance, max_iterations);
  unflatten(v + solve.x, body.v);
  body.x += h * body.v;
  return {solve.iterations, solve.converged};
}

}  // namespace kit
