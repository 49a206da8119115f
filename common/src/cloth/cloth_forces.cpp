// The production cloth force pass (cloth_forces.hpp). Compiled with -fno-math-errno so that the
// square root of a run vectorises, and -fno-trapping-math so that the zero-length guard's
// comparison and divide become a blend rather than a branch (common/CMakeLists.txt).
#include <kit/cloth/cloth_forces.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kit {

ClothForces::ClothForces(const Springs& springs, const Eigen::VectorXd& masses, std::optional<Vec3> gravity,
                         std::optional<double> drag)
    : masses_(masses), gravity_(gravity), drag_(drag) {
  // Order the springs by (offset, a), oriented so that a < b, then cut runs where a stops
  // growing by one: on a grid a run is one row of one family's direction.
  const std::size_t n = springs.size();
  std::vector<std::int32_t> lo(n), hi(n);
  for (std::size_t s = 0; s < n; ++s) {
    lo[s] = std::min(springs.a[s], springs.b[s]);
    hi[s] = std::max(springs.a[s], springs.b[s]);
    by_kind_[int(springs.kind[s])] += 1;
    damped_ = damped_ || springs.damping[s] != 0;
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
    const auto dp = hi[p] - lo[p], dq = hi[q] - lo[q];
    return dp != dq ? dp < dq : lo[p] < lo[q];
  });
  rest_.reserve(n), stiffness_.reserve(n), damping_.reserve(n);
  std::size_t longest = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t s = order[k];
    const std::int32_t offset = hi[s] - lo[s];
    const bool extends = !runs_.empty() && runs_.back().offset == offset &&
                         runs_.back().first_node + runs_.back().length == lo[s];
    if (extends)
      ++runs_.back().length;
    else
      runs_.push_back({lo[s], offset, std::int32_t(k), 1});
    longest = std::max(longest, std::size_t(runs_.back().length));
    rest_.push_back(springs.rest[s]);
    stiffness_.push_back(springs.stiffness[s]);
    damping_.push_back(springs.damping[s]);
  }
  fx_.resize(longest), fy_.resize(longest), fz_.resize(longest);
}

namespace {
// The two loops of the pass are built for AVX-512, AVX2 and the baseline, and the loader picks
// the widest this CPU runs (GCC function multiversioning): the square root and the divide of
// 8 springs at once instead of 2. The rest of the kit keeps the baseline target.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define KIT_WIDEST_VECTORS __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define KIT_WIDEST_VECTORS
#endif

// One run's spring forces on its a-ends, f = [K (L0 − l)/l − μ (Δv·x)/l²] x (x = x_a − x_b),
// into fx, fy, fz. A zero-length spring has no direction and gets no force.
template <bool damped>
KIT_WIDEST_VECTORS void run_forces(const double* __restrict xa, const double* __restrict ya,
                                   const double* __restrict za, const double* __restrict xb,
                                   const double* __restrict yb, const double* __restrict zb,
                                   const double* __restrict vxa, const double* __restrict vya,
                                   const double* __restrict vza, const double* __restrict vxb,
                                   const double* __restrict vyb, const double* __restrict vzb,
                                   const double* __restrict rest, const double* __restrict k,
                                   const double* __restrict mu, double* __restrict fx, double* __restrict fy,
                                   double* __restrict fz, int length) {
  for (int s = 0; s < length; ++s) {
    const double dx = xa[s] - xb[s], dy = ya[s] - yb[s], dz = za[s] - zb[s];
    const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double inv = l > 0 ? 1.0 / l : 0.0;
    double scale = k[s] * (rest[s] - l) * inv;
    if constexpr (damped) {
      const double rate =
          ((vxa[s] - vxb[s]) * dx + (vya[s] - vyb[s]) * dy + (vza[s] - vzb[s]) * dz) * inv * inv;
      scale -= mu[s] * rate;
    }
    fx[s] = scale * dx, fy[s] = scale * dy, fz[s] = scale * dz;
  }
}

// g += sign·f over one run, for each axis. The restrict pointers tell GCC what it cannot prove:
// f's columns and the run's scratch forces do not overlap, so the loop vectorises.
KIT_WIDEST_VECTORS void scatter(double* __restrict gx, double* __restrict gy, double* __restrict gz,
                                const double* __restrict fx, const double* __restrict fy,
                                const double* __restrict fz, int length, double sign) {
  for (int s = 0; s < length; ++s) gx[s] += sign * fx[s], gy[s] += sign * fy[s], gz[s] += sign * fz[s];
}
}  // namespace

void ClothForces::operator()(const NodeArray& x, const NodeArray& v, NodeArray& f) const {
  const long n = nodes();
  f.resize(n, 3);
  if (gravity_)
    for (int axis = 0; axis < 3; ++axis) f.col(axis) = masses_ * (*gravity_)[axis];
  else
    f.setZero();
  if (drag_)
    for (int axis = 0; axis < 3; ++axis) f.col(axis) -= *drag_ * masses_.cwiseProduct(v.col(axis));
  const double *px = x.col(0).data(), *py = x.col(1).data(), *pz = x.col(2).data();
  const double *qx = v.col(0).data(), *qy = v.col(1).data(), *qz = v.col(2).data();
  double *gx = f.col(0).data(), *gy = f.col(1).data(), *gz = f.col(2).data();
  for (const Run& r : runs_) {
    const long a = r.first_node, b = a + r.offset;
    const double *rest = rest_.data() + r.first, *k = stiffness_.data() + r.first,
                 *mu = damping_.data() + r.first;
    if (damped_)
      run_forces<true>(px + a, py + a, pz + a, px + b, py + b, pz + b, qx + a, qy + a, qz + a, qx + b, qy + b,
                       qz + b, rest, k, mu, fx_.data(), fy_.data(), fz_.data(), r.length);
    else
      run_forces<false>(px + a, py + a, pz + a, px + b, py + b, pz + b, qx + a, qy + a, qz + a, qx + b,
                        qy + b, qz + b, rest, k, mu, fx_.data(), fy_.data(), fz_.data(), r.length);
    // Scatter in two passes: within one pass no two springs write the same node, so both
    // vectorise (in one pass, a run of offset 1 would write node a + 1 twice in a row).
    scatter(gx + a, gy + a, gz + a, fx_.data(), fy_.data(), fz_.data(), r.length, 1.0);
    scatter(gx + b, gy + b, gz + b, fx_.data(), fy_.data(), fz_.data(), r.length, -1.0);
  }
  if (work_) {
    ++work_->force_passes;
    work_->spring_terms += long(springs());
    for (int kind = 0; kind < 3; ++kind) work_->spring_terms_by_kind[kind] += by_kind_[kind];
    if (gravity_) work_->gravity_terms += n;
    if (drag_) work_->drag_terms += n;
  }
}

double ClothForces::potential_energy(const NodeArray& x) const {
  double energy = 0;
  for (const Run& r : runs_)
    for (int s = 0; s < r.length; ++s) {
      const long a = r.first_node + s, b = a + r.offset, i = r.first + s;
      const double stretch = (x.row(a) - x.row(b)).norm() - rest_[std::size_t(i)];
      energy += 0.5 * stiffness_[std::size_t(i)] * stretch * stretch;
    }
  if (gravity_) energy -= (masses_.transpose() * x) * *gravity_;
  return energy;
}

double kinetic_energy(const Eigen::VectorXd& masses, const NodeArray& v) {
  return 0.5 * masses.dot(v.rowwise().squaredNorm());
}

double max_strain(const Springs& springs, const NodeArray& x, SpringKind kind) {
  double worst = -1;
  bool any = false;
  for (std::size_t s = 0; s < springs.size(); ++s)
    if (springs.kind[s] == kind) {
      any = true;
      const double l = (x.row(springs.a[s]) - x.row(springs.b[s])).norm();
      if (!std::isfinite(l)) return INFINITY;  // a diverged cloth: no spring length to compare
      worst = std::max(worst, (l - springs.rest[s]) / springs.rest[s]);
    }
  return any ? worst : 0.0;
}

}  // namespace kit
