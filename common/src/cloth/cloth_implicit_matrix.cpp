// The matrix of the implicit step, pattern once and scatter every step (cloth_implicit_matrix.hpp).
#include <kit/cloth/cloth_implicit_matrix.hpp>

#include <algorithm>

namespace kit {

Eigen::VectorXd flatten(const NodeArray& a) {
  Eigen::VectorXd flat(3 * a.rows());
  for (Eigen::Index i = 0; i < a.rows(); ++i) flat.segment<3>(3 * i) = a.row(i).transpose();
  return flat;
}

void unflatten(const Eigen::VectorXd& flat, NodeArray& a) {
  a.resize(flat.size() / 3, 3);
  for (Eigen::Index i = 0; i < a.rows(); ++i) a.row(i) = flat.segment<3>(3 * i).transpose();
}

Mat3 spring_damping_block(const Vec3& xa, const Vec3& xb, double damping) {
  const Vec3 gap = xa - xb;
  const double l = gap.norm();
  if (l == 0 || damping == 0) return Mat3::Zero();
  const Vec3 along = gap / l;
  return -damping * along * along.transpose();
}

void stiffness_times(const Springs& springs, const std::vector<Mat3>& stiffness, const NodeArray& w,
                     Eigen::VectorXd& out) {
  out.setZero(3 * w.rows());
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const auto a = springs.a[s], b = springs.b[s];
    const Vec3 t = stiffness[s] * (w.row(a) - w.row(b)).transpose();
    out.segment<3>(3 * a) += t;
    out.segment<3>(3 * b) -= t;
  }
}

ImplicitMatrix::ImplicitMatrix(const Springs& springs, long nodes, const std::vector<std::int32_t>& pins)
    : pins_(pins) {
  // Each node's block columns: itself and every node a spring joins it to, sorted and unique.
  auto columns = std::vector<std::vector<std::int32_t>>(std::size_t(nodes));
  for (long i = 0; i < nodes; ++i) columns[std::size_t(i)].push_back(std::int32_t(i));
  for (std::size_t s = 0; s < springs.size(); ++s) {
    columns[std::size_t(springs.a[s])].push_back(springs.b[s]);
    columns[std::size_t(springs.b[s])].push_back(springs.a[s]);
  }
  Eigen::VectorXi row_sizes(3 * nodes);
  for (auto& c : columns) {
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
  }
  for (long i = 0; i < nodes; ++i)
    row_sizes.segment<3>(3 * i).setConstant(3 * int(columns[std::size_t(i)].size()));
  matrix.resize(3 * nodes, 3 * nodes);
  matrix.reserve(row_sizes);
  for (long i = 0; i < nodes; ++i)
    for (int r = 0; r < 3; ++r)
      for (std::int32_t j : columns[std::size_t(i)])
        for (int c = 0; c < 3; ++c) matrix.insert(3 * i + r, 3 * j + c) = 0;  // in order: no shifting
  matrix.makeCompressed();

  const auto position = [&](std::int32_t row_node, std::int32_t column_node) {
    const auto& c = columns[std::size_t(row_node)];
    return std::int32_t(std::lower_bound(c.begin(), c.end(), column_node) - c.begin());
  };
  diagonal_.resize(std::size_t(nodes));
  for (long i = 0; i < nodes; ++i) diagonal_[std::size_t(i)] = position(std::int32_t(i), std::int32_t(i));
  slots_.reserve(springs.size());
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const auto a = springs.a[s], b = springs.b[s];
    slots_.push_back({position(a, a), position(a, b), position(b, a), position(b, b)});
  }
  const auto* outer = matrix.outerIndexPtr();
  for (const std::int32_t p : pins_) {
    for (int r = 0; r < 3; ++r)
      for (auto k = outer[3 * p + r]; k < outer[3 * p + r + 1]; ++k)
        if (matrix.innerIndexPtr()[k] != 3 * p + r) pinned_values_.push_back(k);
    for (const std::int32_t q : columns[std::size_t(p)]) {
      if (q == p) continue;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) pinned_values_.push_back(outer[3 * q + r] + 3 * position(q, p) + c);
    }
  }
}

void ImplicitMatrix::assemble(const Springs& springs, const NodeArray& x, const std::vector<Mat3>& stiffness,
                              const Eigen::VectorXd& masses, std::optional<double> drag, double h) {
  double* values = matrix.valuePtr();
  const auto* outer = matrix.outerIndexPtr();
  std::fill(values, values + matrix.nonZeros(), 0.0);
  // Block (row_node, position) += sign·B, B's three rows going to the node's three rows.
  const auto add = [&](std::int32_t row_node, std::int32_t position, const Mat3& block) {
    for (int r = 0; r < 3; ++r) {
      double* row = values + outer[3 * row_node + r] + 3 * position;
      for (int c = 0; c < 3; ++c) row[c] += block(r, c);
    }
  };
  // M − h ∂f/∂v of the drag: m (1 + h c) on the diagonal.
  const double drag_factor = 1 + h * drag.value_or(0.0);
  for (Eigen::Index i = 0; i < masses.size(); ++i)
    for (int r = 0; r < 3; ++r)
      values[outer[3 * i + r] + 3 * diagonal_[std::size_t(i)] + r] += masses[i] * drag_factor;
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const auto a = springs.a[s], b = springs.b[s];
    // B = −h ∂f_a/∂v_a − h² ∂f_a/∂x_a: +B on the diagonal blocks (a, a), (b, b), −B off them.
    Mat3 block = -h * h * stiffness[s];
    if (springs.damping[s] != 0) block -= h * spring_damping_block(x.row(a), x.row(b), springs.damping[s]);
    const SpringSlots& slot = slots_[s];
    add(a, slot.aa, block);
    add(b, slot.bb, block);
    add(a, slot.ab, -block);
    add(b, slot.ba, -block);
  }
}

void ImplicitMatrix::constrain(Eigen::VectorXd& b) {
  double* values = matrix.valuePtr();
  for (const std::int64_t k : pinned_values_) values[k] = 0;
  for (const std::int32_t p : pins_) b.segment<3>(3 * p).setZero();
}

}  // namespace kit
