// Geometric multigrid on a cloth's grid (cloth_multigrid.hpp).
#include <kit/cloth/cloth_multigrid.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace kit {
namespace {

constexpr int coarsest_side = 6;  // nodes: the coarsest grid has at most 6×6, a 108×108 dense solve

// The coarse grid along one side of n nodes: the even-numbered nodes, and the last one.
std::vector<int> coarse_points(int n) {
  std::vector<int> points;
  for (int i = 0; i < n; i += 2) points.push_back(i);
  if ((n - 1) % 2 != 0) points.push_back(n - 1);
  return points;
}

// Linear interpolation along one side: each fine node's coarse neighbours and their weights.
std::vector<std::vector<std::pair<int, double>>> side_parents(int n) {
  const std::vector<int> points = coarse_points(n);
  std::vector<int> coarse_of(std::size_t(n), -1);
  for (std::size_t k = 0; k < points.size(); ++k) coarse_of[std::size_t(points[k])] = int(k);
  auto parents = std::vector<std::vector<std::pair<int, double>>>(std::size_t(n));
  for (int i = 0; i < n; ++i) {
    if (coarse_of[std::size_t(i)] >= 0)
      parents[std::size_t(i)] = {{coarse_of[std::size_t(i)], 1.0}};
    else  // between two coarse points, one node away from each
      parents[std::size_t(i)] = {{coarse_of[std::size_t(i - 1)], 0.5}, {coarse_of[std::size_t(i + 1)], 0.5}};
  }
  return parents;
}

}  // namespace

GridMultigrid::GridMultigrid(int nx, int ny, const SparseMatrix& pattern) {
  if (nx < 1 || ny < 1 || pattern.rows() != 3L * nx * ny || pattern.cols() != pattern.rows() ||
      !pattern.isCompressed())
    throw std::invalid_argument(
        fmt::format("multigrid: a {}×{} grid needs a compressed {}×{} matrix, not {}×{}", nx, ny,
                    3L * nx * ny, 3L * nx * ny, pattern.rows(), pattern.cols()));
  Level finest;
  finest.nx = nx, finest.ny = ny;
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  finest.first.push_back(0);
  for (int i = 0; i < finest.nodes(); ++i) {
    const int begin = outer[3 * i], blocks = (outer[3 * i + 1] - begin) / 3;
    bool block_rows = outer[3 * i + 1] - begin == 3 * blocks && outer[3 * i + 3] - begin == 9 * blocks;
    for (int r = 0; r < 3 && block_rows; ++r)
      for (int k = 0; k < 3 * blocks && block_rows; ++k)
        block_rows = inner[begin + 3 * blocks * r + k] == inner[begin + k / 3 * 3] / 3 * 3 + k % 3;
    if (!block_rows)
      throw std::invalid_argument(
          fmt::format("multigrid: node {}'s rows are not 3×3 blocks in the same columns", i));
    for (int k = 0; k < blocks; ++k) {
      const int j = inner[begin + 3 * k] / 3;
      if (j == i) finest.diagonal.push_back(k);
      finest.column.push_back(j);
    }
    if (int(finest.diagonal.size()) != i + 1)
      throw std::invalid_argument(fmt::format("multigrid: node {} has no diagonal block", i));
    finest.first.push_back(int(finest.column.size()));
    csr_first_.push_back(begin);
  }
  finest.values.assign(finest.column.size(), Block::Zero());
  levels_.push_back(std::move(finest));
  while (levels_.back().nx > coarsest_side || levels_.back().ny > coarsest_side) add_coarser_level();
  for (Level& level : levels_) {
    const auto nodes = std::size_t(level.nodes());
    level.x.assign(nodes, Node::Zero()), level.b.assign(nodes, Node::Zero()),
        level.r.assign(nodes, Node::Zero());
    level.inverse_diagonal.assign(nodes, Block::Zero());
  }
  coarsest_b_.resize(3 * levels_.back().nodes());
}

void GridMultigrid::add_coarser_level() {
  Level& fine = levels_.back();
  Level coarse;
  coarse.nx = int(coarse_points(fine.nx).size()), coarse.ny = int(coarse_points(fine.ny).size());
  // P: bilinear, the product of the two sides' linear interpolations.
  const auto across = side_parents(fine.nx), down = side_parents(fine.ny);
  fine.parent_first = {0};
  for (int j = 0; j < fine.ny; ++j)
    for (int i = 0; i < fine.nx; ++i) {
      for (const auto& [cj, wj] : down[std::size_t(j)])
        for (const auto& [ci, wi] : across[std::size_t(i)]) {
          fine.parent.push_back(cj * coarse.nx + ci);
          fine.weight.push_back(float(wi * wj));
        }
      fine.parent_first.push_back(int(fine.parent.size()));
    }
  // The pattern of Pᵀ A P: coarse I meets coarse J when a parent of i is I, one of j is J, and
  // A has block (i, j).
  const auto parents_of = [&](int i) {
    return std::pair(fine.parent_first[std::size_t(i)], fine.parent_first[std::size_t(i) + 1]);
  };
  std::vector<std::vector<int>> columns(std::size_t(coarse.nodes()));
  for (int i = 0; i < fine.nodes(); ++i)
    for (int e = fine.first[std::size_t(i)]; e < fine.first[std::size_t(i) + 1]; ++e) {
      const auto [a0, a1] = parents_of(i);
      const auto [b0, b1] = parents_of(fine.column[std::size_t(e)]);
      for (int a = a0; a < a1; ++a)
        for (int b = b0; b < b1; ++b)
          columns[std::size_t(fine.parent[std::size_t(a)])].push_back(fine.parent[std::size_t(b)]);
    }
  coarse.first = {0};
  for (int I = 0; I < coarse.nodes(); ++I) {
    std::vector<int>& c = columns[std::size_t(I)];
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    coarse.diagonal.push_back(int(std::lower_bound(c.begin(), c.end(), I) - c.begin()));
    coarse.column.insert(coarse.column.end(), c.begin(), c.end());
    coarse.first.push_back(int(coarse.column.size()));
  }
  coarse.values.assign(coarse.column.size(), Block::Zero());
  // The plan: for each fine block, where each of its weighted copies goes.
  fine.term_first = {0};
  for (int i = 0; i < fine.nodes(); ++i)
    for (int e = fine.first[std::size_t(i)]; e < fine.first[std::size_t(i) + 1]; ++e) {
      const auto [a0, a1] = parents_of(i);
      const auto [b0, b1] = parents_of(fine.column[std::size_t(e)]);
      for (int a = a0; a < a1; ++a) {
        const int I = fine.parent[std::size_t(a)];
        const auto row_begin = coarse.column.begin() + coarse.first[std::size_t(I)];
        const auto row_end = coarse.column.begin() + coarse.first[std::size_t(I) + 1];
        for (int b = b0; b < b1; ++b) {
          fine.term_target.push_back(
              int(std::lower_bound(row_begin, row_end, fine.parent[std::size_t(b)]) - coarse.column.begin()));
          fine.term_weight.push_back(fine.weight[std::size_t(a)] * fine.weight[std::size_t(b)]);
        }
      }
      fine.term_first.push_back(int(fine.term_target.size()));
    }
  levels_.push_back(std::move(coarse));
}

bool GridMultigrid::setup(const SparseMatrix& A) {
  Level& finest = levels_[0];
  if (A.rows() != 3L * finest.nodes() || A.nonZeros() != 9L * Eigen::Index(finest.column.size()))
    throw std::invalid_argument("multigrid: A does not have the pattern the levels were built for");
  // The finest blocks, out of Eigen's rows (node i's three rows one after the other, each with
  // all its blocks) into blocks of single precision.
  const double* values = A.valuePtr();
  for (int i = 0; i < finest.nodes(); ++i) {
    const int first = finest.first[std::size_t(i)], blocks = finest.first[std::size_t(i) + 1] - first;
    for (int k = 0; k < blocks; ++k) {
      Block& block = finest.values[std::size_t(first + k)];
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          block(r, c) = float(values[csr_first_[std::size_t(i)] + 3 * blocks * r + 3 * k + c]);
    }
  }
  // Pᵀ A P, level by level: every term adds a weighted fine block to a coarse one.
  for (std::size_t l = 0; l + 1 < levels_.size(); ++l) {
    const Level& fine = levels_[l];
    Level& coarse = levels_[l + 1];
    std::fill(coarse.values.begin(), coarse.values.end(), Block::Zero());
    Block* out = coarse.values.data();  // raw pointers: the compiler may keep them in registers
    const int* term_first = fine.term_first.data();
    const int* target = fine.term_target.data();
    const float* weight = fine.term_weight.data();
    for (std::size_t e = 0; e < fine.values.size(); ++e) {
      const Block block = fine.values[e];
      for (int t = term_first[e]; t < term_first[e + 1]; ++t) out[target[t]] += weight[t] * block;
    }
  }
  bool invertible = true;
  for (Level& level : levels_)
    for (int i = 0; i < level.nodes(); ++i) {
      const Block& d =
          level.values[std::size_t(level.first[std::size_t(i)] + level.diagonal[std::size_t(i)])];
      Block& inverse = level.inverse_diagonal[std::size_t(i)];
      inverse.topRows<3>() = d.topRows<3>().cast<double>().inverse().cast<float>();
      invertible = invertible && inverse.allFinite();
    }
  const Level& last = levels_.back();
  coarsest_matrix_.setZero(3 * last.nodes(), 3 * last.nodes());
  for (int i = 0; i < last.nodes(); ++i)
    for (int e = last.first[std::size_t(i)]; e < last.first[std::size_t(i) + 1]; ++e)
      coarsest_matrix_.block<3, 3>(3 * i, 3 * last.column[std::size_t(e)]) =
          last.values[std::size_t(e)].topRows<3>().cast<double>();
  coarsest_.compute(coarsest_matrix_);
  return invertible && coarsest_.info() == Eigen::Success;
}

// Σ_k A_ik x_k over node i's blocks begin ≤ k < end (to the last: end = −1): the columns of each
// block times the matching entries of x_k, four floats at a time.
GridMultigrid::Node GridMultigrid::row_product(const Level& level, int i, int begin, int end) {
  const int first = level.first[std::size_t(i)];
  const int last = first + (end < 0 ? level.first[std::size_t(i) + 1] - first : end);
  Node sum = Node::Zero();
  for (int e = first + begin; e < last; ++e) {
    const Block& a = level.values[std::size_t(e)];
    const Node& x = level.x[std::size_t(level.column[std::size_t(e)])];
    sum += a.col(0) * x[0] + a.col(1) * x[1] + a.col(2) * x[2];
  }
  return sum;
}

// Node-block Gauss–Seidel: x_i += D_i⁻¹ (b_i − (A x)_i), node after node, in order or reversed.
// From zero, the nodes still ahead hold zero: the forward sweep stops at the diagonal.
void GridMultigrid::smooth(Level& level, bool forward, bool from_zero) {
  const int n = level.nodes();
  for (int s = 0; s < n; ++s) {
    const int i = forward ? s : n - 1 - s;
    const Node gap =
        level.b[std::size_t(i)] - row_product(level, i, 0, from_zero ? level.diagonal[std::size_t(i)] : -1);
    const Block& d = level.inverse_diagonal[std::size_t(i)];
    level.x[std::size_t(i)] += d.col(0) * gap[0] + d.col(1) * gap[1] + d.col(2) * gap[2];
  }
}

// r = b − A x just after a forward sweep from zero: each node's equation held with the blocks
// up to its own when it was updated, so only those after it are left, r_i = −Σ_{k>i} A_ik x_k.
void GridMultigrid::residual_after_forward_sweep(Level& level) {
  for (int i = 0; i < level.nodes(); ++i)
    level.r[std::size_t(i)] = -row_product(level, i, level.diagonal[std::size_t(i)] + 1, -1);
}

void GridMultigrid::cycle(std::size_t l) {
  Level& level = levels_[l];
  if (l + 1 == levels_.size()) {  // exactly, in double
    for (int i = 0; i < level.nodes(); ++i)
      coarsest_b_.segment<3>(3 * i) = level.b[std::size_t(i)].head<3>().cast<double>();
    const Eigen::VectorXd x = coarsest_.solve(coarsest_b_);
    for (int i = 0; i < level.nodes(); ++i)
      level.x[std::size_t(i)] << x.segment<3>(3 * i).cast<float>(), 0.0f;
    return;
  }
  std::fill(level.x.begin(), level.x.end(), Node::Zero());
  smooth(level, true, true);
  residual_after_forward_sweep(level);
  Level& coarse = levels_[l + 1];
  std::fill(coarse.b.begin(), coarse.b.end(), Node::Zero());  // Pᵀ r
  for (int i = 0; i < level.nodes(); ++i)
    for (int k = level.parent_first[std::size_t(i)]; k < level.parent_first[std::size_t(i) + 1]; ++k)
      coarse.b[std::size_t(level.parent[std::size_t(k)])] +=
          level.weight[std::size_t(k)] * level.r[std::size_t(i)];
  cycle(l + 1);
  for (int i = 0; i < level.nodes(); ++i)  // x += P x_c
    for (int k = level.parent_first[std::size_t(i)]; k < level.parent_first[std::size_t(i) + 1]; ++k)
      level.x[std::size_t(i)] +=
          level.weight[std::size_t(k)] * coarse.x[std::size_t(level.parent[std::size_t(k)])];
  smooth(level, false, false);
}

void GridMultigrid::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  Level& finest = levels_[0];
  for (int i = 0; i < finest.nodes(); ++i)
    finest.b[std::size_t(i)] << r.segment<3>(3 * i).cast<float>(), 0.0f;
  cycle(0);
  z.resize(r.size());
  for (int i = 0; i < finest.nodes(); ++i)
    z.segment<3>(3 * i) = finest.x[std::size_t(i)].head<3>().cast<double>();
}

PcgResult multigrid_pcg(const SparseMatrix& A, const Eigen::VectorXd& b, const std::vector<Mat3>& filters,
                        GridMultigrid& multigrid, double tolerance, int max_iterations) {
  const auto project = [&filters](Eigen::VectorXd& w) {  // w ← S w, node by node
    for (std::size_t i = 0; i < filters.size(); ++i)
      w.segment<3>(3 * Eigen::Index(i)) = filters[i] * w.segment<3>(3 * Eigen::Index(i));
  };
  PcgResult result;
  Eigen::VectorXd residual = b, preconditioned, direction, product;
  project(residual);
  const double start = residual.norm(), goal = tolerance * start;
  result.x.setZero(b.size());
  double residual_norm = residual.norm();
  if (residual_norm <= goal || max_iterations <= 0) {  // nothing to do (S b = 0), or not allowed to
    result.converged = residual_norm <= goal;
    result.residual = start > 0 ? residual_norm / start : 0.0;
    return result;
  }
  // The search directions stay in S's range: the preconditioned residual is filtered again.
  multigrid.apply(residual, preconditioned);
  project(preconditioned);
  direction = preconditioned;
  double rho = residual.dot(preconditioned);
  while (residual_norm > goal && result.iterations < max_iterations) {
    if (!(rho > 0)) {  // the cycle is not positive on this residual: no descent direction
      result.negative_curvature = true;
      break;
    }
    product.noalias() = A * direction;
    project(product);
    ++result.iterations;
    const double pAp = direction.dot(product);
    if (!(pAp > 0)) {
      result.negative_curvature = true;
      break;
    }
    const double step = rho / pAp;
    result.x += step * direction;
    residual -= step * product;
    residual_norm = residual.norm();
    if (residual_norm <= goal) break;
    multigrid.apply(residual, preconditioned);
    project(preconditioned);
    const double rho_next = residual.dot(preconditioned);
    direction = preconditioned + (rho_next / rho) * direction;
    rho = rho_next;
  }
  result.residual = start > 0 ? residual_norm / start : 0.0;
  result.converged = !result.negative_curvature && residual_norm <= goal;
  return result;
}

}  // namespace kit
