// Liu et al. 2013's local/global step (cloth_liu.hpp).
#include <kit/cloth/cloth_liu.hpp>

#include <algorithm>

namespace kit {

LiuStepper::LiuStepper(const ClothSystem& cloth, int iterations)
    : iterations_(iterations), free_(std::size_t(cloth.x.rows()), 0) {
  if (iterations < 1) throw std::invalid_argument("Liu et al.'s method needs at least one iteration");
  for (const std::int32_t p : cloth.pins()) free_[std::size_t(p)] = -1;
  for (auto& row : free_)
    if (row == 0) row = std::int32_t(free_count_++);  // a free node's row; pinned ones keep −1
}

void LiuStepper::factorise(const ClothSystem& cloth, double h) {
  // M (1 + h c) + h² L over the free nodes: L gains K_s at (a, a), (b, b) and −K_s at (a, b), (b, a).
  const double drag = 1 + h * cloth.scene().drag.value_or(0.0);
  const Springs& springs = cloth.springs();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(std::size_t(free_count_) + 4 * springs.size());
  for (std::size_t i = 0; i < free_.size(); ++i)
    if (free_[i] >= 0) entries.emplace_back(free_[i], free_[i], cloth.masses()[Eigen::Index(i)] * drag);
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const double w = h * h * springs.stiffness[s];
    const auto fa = free_[std::size_t(springs.a[s])], fb = free_[std::size_t(springs.b[s])];
    if (fa >= 0) entries.emplace_back(fa, fa, w);
    if (fb >= 0) entries.emplace_back(fb, fb, w);
    if (fa >= 0 && fb >= 0) entries.emplace_back(fa, fb, -w), entries.emplace_back(fb, fa, -w);
  }
  Eigen::SparseMatrix<double> global(free_count_, free_count_);
  global.setFromTriplets(entries.begin(), entries.end());
  cholesky_.compute(global);
  if (cholesky_.info() != Eigen::Success)
    throw SolveFailed("the sparse Cholesky factorisation of M + h² L failed");
  factorised_h_ = h;
  ++work.factorizations;
}

void LiuStepper::step(ClothSystem& cloth, double h) {
  if (h != factorised_h_) factorise(cloth, h);
  // Drag c in backward Euler, M (1 + h c)(x − x_n) = h M v_n + h² (M g + f_springs): the same
  // minimisation with masses M (1 + h c) and y = x_n + (h v_n + h² g)/(1 + h c).
  const double drag = 1 + h * cloth.scene().drag.value_or(0.0);
  const Springs& springs = cloth.springs();
  const Eigen::VectorXd& m = cloth.masses();
  const Vec3 g = cloth.scene().gravity.value_or(Vec3::Zero());
  // y = x_n + h v_n + h² g, the inertial guess, and the first iterate.
  y_.resize(free_count_, 3);
  NodeArray x = cloth.x;
  for (std::size_t i = 0; i < free_.size(); ++i)
    if (const auto row = free_[i]; row >= 0) {
      const auto n = Eigen::Index(i);
      y_.row(row) = cloth.x.row(n) + (h * cloth.v.row(n) + h * h * g.transpose()) / drag;
      x.row(n) = y_.row(row);
    }
  for (int k = 0; k < iterations_; ++k) {
    rhs_ = y_;
    for (std::size_t i = 0; i < free_.size(); ++i)
      if (free_[i] >= 0) rhs_.row(free_[i]) *= m[Eigen::Index(i)] * drag;
    for (std::size_t s = 0; s < springs.size(); ++s) {
      const auto a = springs.a[s], b = springs.b[s];
      const Vec3 p = x.row(a) - x.row(b);
      const double l = p.norm();
      // local: the spring's nearest rest-length vector d to the present x_a − x_b
      const Vec3 d = l > 0 ? Vec3(springs.rest[s] / l * p) : Vec3::Zero();
      const double w = h * h * springs.stiffness[s];
      const auto fa = free_[std::size_t(a)], fb = free_[std::size_t(b)];
      if (fa >= 0) rhs_.row(fa) += w * (d + (fb < 0 ? Vec3(x.row(b)) : Vec3::Zero())).transpose();
      if (fb >= 0) rhs_.row(fb) += w * ((fa < 0 ? Vec3(x.row(a)) : Vec3::Zero()) - d).transpose();
    }
    solution_ = cholesky_.solve(rhs_);  // global
    if (!solution_.allFinite()) throw SolveFailed("Liu et al.'s global solve returned non-finite positions");
    for (std::size_t i = 0; i < free_.size(); ++i)
      if (free_[i] >= 0) x.row(Eigen::Index(i)) = solution_.row(free_[i]);
    ++work.local_global;
  }
  cloth.v = (x - cloth.x) / h;
  cloth.x = x;
  ++work.steps;
  cloth.finish_step(h);
}

}  // namespace kit
