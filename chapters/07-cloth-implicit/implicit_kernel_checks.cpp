// Ex 7.1-7.3 measured against the kit's own computations (implicit_kernel_checks.hpp).
#include "implicit_kernel_checks.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <kit/app/report.hpp>
#include <kit/base/random.hpp>
#include <kit/base/stopwatch.hpp>
#include <kit/cloth/cloth_stability.hpp>

namespace kit {
namespace {

Vec3 random_direction(Random& random) {
  for (;;) {
    const Vec3 d(random.symmetric(), random.symmetric(), random.symmetric());
    if (const double n = d.norm(); n > 0.1 && n <= 1) return d / n;
  }
}

/// The force on a of an undamped spring, f_a = −K (l − L0) x̂ [N]: what the block derives from.
Vec3 hooke(const Vec3& xa, const Vec3& xb, double rest, double stiffness) {
  const Vec3 gap = xa - xb;
  const double l = gap.norm();
  return -stiffness * (l - rest) / l * gap;
}

double lowest_eigenvalue(const Mat3& m) {
  return Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (m + m.transpose())).eigenvalues().minCoeff();
}

double max_abs(const SparseMatrix& m) {
  return m.nonZeros() ? Eigen::Map<const Eigen::VectorXd>(m.valuePtr(), m.nonZeros()).cwiseAbs().maxCoeff()
                      : 0.0;
}

std::vector<Mat3> blocks(const Springs& springs, const NodeArray& x, SpringStiffnessBlock block, bool clamp) {
  std::vector<Mat3> out(springs.size());
  for (std::size_t s = 0; s < springs.size(); ++s)
    out[s] = block(x.row(springs.a[s]), x.row(springs.b[s]), springs.rest[s], springs.stiffness[s], clamp);
  return out;
}

bool cholesky_succeeds(const SparseMatrix& a) {
  const Eigen::SparseMatrix<double> column_major = a;
  return Eigen::SimplicialLLT<Eigen::SparseMatrix<double>>(column_major).info() == Eigen::Success;
}

std::vector<std::int32_t> pins_of(const ClothScene& scene) {
  std::vector<std::int32_t> pins;
  for (const Pin& p : scene.pins) pins.push_back(std::int32_t(pinned_node(scene.grid, p)));
  return pins;
}

}  // namespace

JacobianCheck check_stiffness_block(SpringStiffnessBlock block, int springs) {
  Random random(20261122);
  JacobianCheck c;
  c.springs = springs;
  for (int s = 0; s < springs; ++s) {
    const double rest = 0.1 + 1.9 * random.unit(), stiffness = std::pow(10.0, 4 * random.unit());
    const double length = rest * (0.5 + 1.5 * random.unit());
    const Vec3 xb(random.symmetric(), random.symmetric(), random.symmetric());
    const Vec3 xa = xb + length * random_direction(random);
    const Mat3 j = block(xa, xb, rest, stiffness, false);
    Mat3 numeric;
    const double step = 1e-6 * length;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = step * Vec3::Unit(k);
      numeric.col(k) = (hooke(xa + e, xb, rest, stiffness) - hooke(xa - e, xb, rest, stiffness)) / (2 * step);
    }
    c.finite_difference = std::max(c.finite_difference, (j - numeric).norm() / j.norm());
    c.asymmetry = std::max(c.asymmetry, (j - j.transpose()).norm() / j.norm());
    if (length < rest) {
      c.clamped_lowest =
          std::min(c.clamped_lowest, lowest_eigenvalue(-block(xa, xb, rest, stiffness, true)) / stiffness);
      c.unclamped_lowest = std::min(c.unclamped_lowest, lowest_eigenvalue(-j) / stiffness);
    }
  }
  return c;
}

AssemblyCheck check_assembly(const ClothScene& scene, const Springs& springs, ImplicitKernels kernels,
                             double h) {
  AssemblyCheck c;
  const ClothGrid& grid = scene.grid;
  const Eigen::VectorXd masses = grid.node_masses();
  const ClothForces forces(springs, masses, scene.gravity, scene.drag);
  const std::vector<std::int32_t> pins = pins_of(scene);
  // A disturbed state: every node off its rest place by up to 2% of a cell, moving up to 0.1 m/s.
  Random random(7);
  NodeArray x = grid.rest_positions(), v(x.rows(), 3), f;
  for (Eigen::Index i = 0; i < x.rows(); ++i)
    for (int k = 0; k < 3; ++k)
      x(i, k) += 0.02 * grid.dx() * random.symmetric(), v(i, k) = 0.1 * random.symmetric();
  forces(x, v, f);
  const std::vector<Mat3> stiffness = blocks(springs, x, kernels.stiffness_block, true);
  ImplicitMatrix kit_matrix(springs, x.rows(), pins);
  SparseMatrix a;
  Eigen::VectorXd b, kit_b;
  const ImplicitSystemInput input{springs, x, v, f, masses, stiffness, scene.drag, h};
  time_per_call([&] { return kernels.assemble(input, a, b), 0; }, c.triplet_seconds);
  time_per_call([&] { return kit_matrix.assemble(springs, x, stiffness, masses, scene.drag, h), 0; },
                c.scatter_seconds);
  stiffness_times(springs, stiffness, v, kit_b);
  kit_b = h * (flatten(f) + h * kit_b);
  const SparseMatrix& ak = kit_matrix.matrix;
  c.rows = ak.rows(), c.nonzeros = ak.nonZeros();
  const double scale = max_abs(ak);
  c.matrix_difference =
      a.rows() == ak.rows() && a.cols() == ak.cols() ? max_abs(SparseMatrix(a - ak)) / scale : INFINITY;
  c.rhs_difference =
      b.size() == kit_b.size() ? (b - kit_b).cwiseAbs().maxCoeff() / kit_b.cwiseAbs().maxCoeff() : INFINITY;
  c.asymmetry = max_abs(SparseMatrix(a - SparseMatrix(a.transpose()))) / scale;
  c.definite = cholesky_succeeds(a);
  // The sheet squeezed to 70% in its plane, a little rumpled: compressed springs everywhere.
  const Vec3 centre = x.colwise().mean();
  NodeArray squeezed = x;
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    const Vec3 r = x.row(i).transpose() - centre;
    squeezed.row(i) = (centre + 0.7 * r + 0.05 * grid.dx() * random_direction(random)).transpose();
  }
  forces(squeezed, v, f);
  const std::vector<Mat3> unclamped = blocks(springs, squeezed, kernels.stiffness_block, false);
  kit_matrix.assemble(springs, squeezed, unclamped, masses, scene.drag, h);
  c.unclamped_definite = cholesky_succeeds(kit_matrix.matrix);
  std::vector<Mat3> filters(std::size_t(x.rows()), Mat3::Identity());
  for (const std::int32_t p : pins) filters[std::size_t(p)].setZero();
  c.unclamped_solve = kernels.pcg(kit_matrix.matrix, h * flatten(f), filters, 1e-8, int(3 * x.rows()));
  return c;
}

void say_jacobian_check(Report& report, const JacobianCheck& c) {
  report.say("jacobian",
             "1. Your ∂f_a/∂x_a on {n} random springs: {fd:.1e} from central differences "
             "of the force, symmetric to {asymmetry:.1e}. Compressed, the lowest eigenvalue of "
             "−∂f_a/∂x_a is {clamped:.3g} K clamped, {unclamped:.3g} K not (< 0: indefinite).\n\n",
             {{"n", long(c.springs)},
              {"fd", c.finite_difference},
              {"asymmetry", c.asymmetry},
              {"clamped", c.clamped_lowest},
              {"unclamped", c.unclamped_lowest}});
}

void say_assembly_check(Report& report, const AssemblyCheck& c, const std::string& scene, double h) {
  const PcgResult& pcg = c.unclamped_solve;
  report.say("system",
             "2. '{scene}' at h = {h:.4g} s: A is {rows}×{rows}, {nonzeros} nonzeros. "
             "Your ex 7.2 matches the kit's scatter to {matrix:.1e} (A) and {rhs:.1e} (b); A is "
             "symmetric to {asymmetry:.1e} and {definite}. Your triplets took {triplet_ms:.3g} ms, the "
             "scatter {scatter_ms:.3g} ms. Squeezed to 70% without the clamp, A is {unclamped}; your "
             "PCG {outcome} after {iterations} iterations.\n\n",
             {{"scene", scene},
              {"h", h},
              {"rows", c.rows},
              {"nonzeros", c.nonzeros},
              {"matrix", c.matrix_difference},
              {"rhs", c.rhs_difference},
              {"asymmetry", c.asymmetry},
              {"definite", c.definite ? "positive definite" : "NOT positive definite"},
              {"triplet_ms", 1e3 * c.triplet_seconds},
              {"scatter_ms", 1e3 * c.scatter_seconds},
              {"unclamped", c.unclamped_definite ? "still definite" : "indefinite"},
              {"outcome", pcg.negative_curvature ? "stopped on negative curvature (cᵀAc ≤ 0)"
                          : pcg.converged        ? "converged"
                                                 : "did not converge"},
              {"iterations", long(pcg.iterations)},
              {"negative_curvature", pcg.negative_curvature}});
}

}  // namespace kit
