#include <kit/fem/fem_statics.hpp>

#include <algorithm>
#include <vector>

#include <fmt/format.h>
#include <Eigen/SparseCholesky>

namespace kit {
namespace {

/// The largest in-plane distance of a node from its rest place [m].
double largest_displacement(const FemBody& body) {
  double largest = 0;
  for (long i = 0; i < body.nodes(); ++i)
    largest =
        std::max(largest, (body.x.row(i).head<2>().transpose() - body.mesh().nodes[i]).cwiseAbs().maxCoeff());
  return largest;
}

/// Newton's method at the body's present loads, from its present positions.
StaticSolve newton(FemBody& body, int max_iterations, double tolerance) {
  const std::vector<int> free = free_coordinates(body);
  std::vector<int> slot(3 * body.nodes(), -1);
  for (std::size_t k = 0; k < free.size(); ++k) slot[free[k]] = static_cast<int>(k);
  const double load = std::max(body.loads.norm(), 1e-300);
  StaticSolve out;
  NodeArray f;
  SparseMatrix K;
  Eigen::SparseMatrix<double> reduced(static_cast<Eigen::Index>(free.size()),
                                      static_cast<Eigen::Index>(free.size()));
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  double last_step = 0;  // the largest coordinate change of the last Newton step [m]
  for (;;) {
    body.forces(f);
    Eigen::VectorXd rhs(free.size());
    for (std::size_t k = 0; k < free.size(); ++k) rhs[k] = f(free[k] / 3, free[k] % 3);
    out.residual = rhs.norm() / load;
    if (out.residual <= tolerance || (out.iterations > 1 && last_step <= 1e-9 * largest_displacement(body))) {
      out.converged = true;
      return out;
    }
    if (out.iterations == max_iterations) {
      out.failure =
          fmt::format("no convergence in {} Newton steps (residual {:.2g})", max_iterations, out.residual);
      return out;
    }
    body.stiffness(K);  // the same pattern every step: the ordering is found once
    entries.clear();
    for (int row = 0; row < K.outerSize(); ++row)
      for (SparseMatrix::InnerIterator it(K, row); it; ++it)
        if (slot[row] >= 0 && slot[it.col()] >= 0)
          entries.emplace_back(slot[row], slot[it.col()], -it.value());
    reduced.setFromTriplets(entries.begin(), entries.end());
    if (out.iterations == 0) solver.analyzePattern(reduced);
    solver.factorize(reduced);
    if (solver.info() != Eigen::Success) {
      out.failure = "the stiffness matrix is singular: is the body held?";
      return out;
    }
    const Eigen::VectorXd dx = solver.solve(rhs);
    if (!dx.allFinite()) {
      out.failure = "a Newton step that is not finite";
      return out;
    }
    for (std::size_t k = 0; k < free.size(); ++k) body.x(free[k] / 3, free[k] % 3) += dx[k];
    last_step = dx.cwiseAbs().maxCoeff();
    ++out.iterations;
  }
}

}  // namespace

StaticSolve solve_static(FemBody& body, int max_iterations, double tolerance) {
  const NodeArray start = body.x, loads = body.loads;
  StaticSolve out;
  int spent = 0;
  for (int increments = 1; increments <= 64; increments *= 4) {
    body.x = start;
    for (int k = 1; k <= increments; ++k) {
      body.loads = loads * (static_cast<double>(k) / increments);
      out = newton(body, max_iterations, tolerance);
      spent += out.iterations;
      if (!out.converged) break;
    }
    body.loads = loads;
    out.iterations = spent;
    out.increments = increments;
    if (out.converged) return out;
  }
  out.failure += " (the load in up to 64 increments)";
  return out;
}

}  // namespace kit
