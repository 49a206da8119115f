#include <kit/fem/fem_body.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace kit {

namespace {

void require_positive(double value, const char* what) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(fmt::format("{} {}: expected a positive finite number", what, value));
}

/// One spring per mesh edge, of stiffness E t ΣA / |e|² over the triangles beside it. Chapter 6's
/// springs come in families; here every edge is its own, so all are filed as structural.
Springs edge_springs(const TriangleMesh& mesh, const FemMaterial& material) {
  std::map<std::pair<int, int>, double> beside;  // edge (low, high) → area of its triangles [m²]
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      beside[{std::min(a, b), std::max(a, b)}] += triangle_area(mesh, t);
    }
  }
  Springs springs;
  springs.reserve(beside.size());
  for (const auto& [edge, area] : beside) {
    const double length = (mesh.nodes[edge.first] - mesh.nodes[edge.second]).norm();
    const SpringFamily family{material.young * material.thickness * area / (length * length), 0.0};
    springs.add(edge.first, edge.second, length, family, SpringKind::structural);
  }
  return springs;
}

Vec3 node3(const NodeArray& x, int i) { return x.row(i).transpose(); }

/// The node pairs whose 3×3 blocks each element (3 × 3 pairs) or spring (a-a, a-b, b-a, b-b)
/// fills, in the order stiffness() fills them.
std::vector<std::pair<int, int>> block_pairs(const TriangleMesh& mesh, const Springs& springs,
                                             bool by_springs) {
  std::vector<std::pair<int, int>> pairs;
  if (by_springs) {
    for (std::size_t s = 0; s < springs.size(); ++s) {
      const int a = springs.a[s], b = springs.b[s];
      pairs.insert(pairs.end(), {{a, a}, {a, b}, {b, a}, {b, b}});
    }
  } else {
    for (const auto& tri : mesh.triangles)
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) pairs.emplace_back(tri[a], tri[b]);
  }
  return pairs;
}

}  // namespace

FemBody::FemBody(TriangleMesh mesh, const FemMaterial& material, FemModel model,
                 const ContinuumKernels& kernels)
    : mesh_(std::move(mesh)),
      material_(material),
      model_(model),
      kernels_(kernels),
      lame_(plane_stress_lame(material.young, material.poisson)) {
  require_positive(material.density, "density [kg/m³]");
  require_positive(material.thickness, "thickness [m]");
  const long n = nodes();
  x = NodeArray::Zero(n, 3);
  for (long i = 0; i < n; ++i) x.row(i).head<2>() = mesh_.nodes[i].transpose();
  v = NodeArray::Zero(n, 3);
  loads = NodeArray::Zero(n, 3);
  masses = Eigen::VectorXd::Zero(n);
  filters.assign(n, Mat3::Identity());
  rest_.reserve(mesh_.triangles.size());
  for (const auto& tri : mesh_.triangles) {
    rest_.push_back(
        rest_triangle(mesh_.nodes[tri[0]], mesh_.nodes[tri[1]], mesh_.nodes[tri[2]], material.thickness));
    for (const int node : tri) masses[node] += material.density * rest_.back().volume / 3;
  }
  if (model_ == FemModel::springs) springs_ = edge_springs(mesh_, material_);
  if (model_ == FemModel::linear)
    for (const auto& rest : rest_)
      linear_stiffness_.push_back(linear_stiffness(rest.inverse, rest.volume, lame_));
  // The stiffness's pattern, once: a zero for every entry of every block, summed into place.
  const auto pairs = block_pairs(mesh_, springs_, model_ == FemModel::springs);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * pairs.size());
  for (const auto& [a, b] : pairs)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) entries.emplace_back(3 * a + r, 3 * b + c, 0.0);
  pattern_.resize(3 * n, 3 * n);
  pattern_.setFromTriplets(entries.begin(), entries.end());
  // Where each block's rows start in the values: block (a, b), row r starts at the position of
  // column 3b in row 3a + r, and its three columns follow (the pattern holds all of them).
  slots_.reserve(3 * pairs.size());
  for (const auto& [a, b] : pairs)
    for (int r = 0; r < 3; ++r) {
      const int row = 3 * a + r;
      const int* first = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[row];
      const int* last = pattern_.innerIndexPtr() + pattern_.outerIndexPtr()[row + 1];
      slots_.push_back(static_cast<int>(std::lower_bound(first, last, 3 * b) - pattern_.innerIndexPtr()));
    }
}

void FemBody::hold_in_plane() {
  for (auto& filter : filters) filter(2, 2) = 0;
}

Matrix32 FemBody::gradient(std::size_t t) const {
  const auto& tri = mesh_.triangles[t];
  return kernels_.element.deformation_gradient(node3(x, tri[0]), node3(x, tri[1]), node3(x, tri[2]),
                                               rest_[t].inverse);
}

void FemBody::forces(NodeArray& out, double drag) const {
  out = loads;
  if (drag != 0) out -= drag * (masses.asDiagonal() * v);
  if (model_ == FemModel::springs) {
    for (std::size_t s = 0; s < springs_.size(); ++s) {
      const int a = springs_.a[s], b = springs_.b[s];
      const Vec3 f = kernels_.spring_force(node3(x, a), node3(x, b), node3(v, a), node3(v, b),
                                           springs_.rest[s], SpringFamily{springs_.stiffness[s], 0.0});
      out.row(a) += f.transpose();
      out.row(b) -= f.transpose();
    }
    return;
  }
  for (std::size_t t = 0; t < rest_.size(); ++t) {
    const Matrix32 F = gradient(t);
    const ElementForces f = model_ == FemModel::stvk
                                ? kernels_.element.forces(F, rest_[t].inverse, rest_[t].volume, lame_)
                                : linear_forces(F, rest_[t].inverse, rest_[t].volume, lame_);
    const auto& tri = mesh_.triangles[t];
    for (int k = 0; k < 3; ++k) out.row(tri[k]) += f.col(k).transpose();
  }
}

void FemBody::stiffness(SparseMatrix& out) const {
  const bool same_pattern = out.rows() == pattern_.rows() && out.nonZeros() == pattern_.nonZeros() &&
                            std::equal(pattern_.outerIndexPtr(),
                                       pattern_.outerIndexPtr() + pattern_.rows() + 1, out.outerIndexPtr()) &&
                            std::equal(pattern_.innerIndexPtr(),
                                       pattern_.innerIndexPtr() + pattern_.nonZeros(), out.innerIndexPtr());
  if (!same_pattern) out = pattern_;
  double* values = out.valuePtr();
  std::fill(values, values + out.nonZeros(), 0.0);
  const int* slot = slots_.data();
  const auto add_block = [&](const auto& block) {  // the next block in block_pairs' order
    for (int r = 0; r < 3; ++r, ++slot)
      for (int c = 0; c < 3; ++c) values[*slot + c] += block(r, c);
  };
  if (model_ == FemModel::springs) {
    for (std::size_t s = 0; s < springs_.size(); ++s) {
      const int a = springs_.a[s], b = springs_.b[s];
      const Mat3 J =
          kernels_.spring_stiffness(node3(x, a), node3(x, b), springs_.rest[s], springs_.stiffness[s], false);
      add_block(J);   // a-a
      add_block(-J);  // a-b
      add_block(-J);  // b-a
      add_block(J);   // b-b
    }
    return;
  }
  for (std::size_t t = 0; t < rest_.size(); ++t) {
    const Matrix9 K = model_ == FemModel::stvk
                          ? kernels_.element.stiffness(gradient(t), rest_[t].inverse, rest_[t].volume, lame_)
                          : linear_stiffness_[t];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) add_block(K.block<3, 3>(3 * a, 3 * b));
  }
}

double FemBody::elastic_energy() const {
  double energy = 0;
  if (model_ == FemModel::springs) {
    for (std::size_t s = 0; s < springs_.size(); ++s) {
      const double stretch = (x.row(springs_.a[s]) - x.row(springs_.b[s])).norm() - springs_.rest[s];
      energy += 0.5 * springs_.stiffness[s] * stretch * stretch;
    }
    return energy;
  }
  for (std::size_t t = 0; t < rest_.size(); ++t) {
    const Matrix32 F = gradient(t);
    if (model_ == FemModel::stvk) {
      // W = V (μ E:E + ½λ tr(E)²), with E from the student's ex 9.1.
      const Matrix2 E = kernels_.element.green_strain(F);
      energy += rest_[t].volume * (lame_.mu * E.squaredNorm() + 0.5 * lame_.lambda * E.trace() * E.trace());
    } else {
      const Matrix2 strain = cauchy_strain(F);  // W = ½ V σ:ε
      energy += 0.5 * rest_[t].volume * (linear_stress(strain, lame_).array() * strain.array()).sum();
    }
  }
  return energy;
}

double FemBody::largest_green_strain() const {
  double largest = 0;
  for (std::size_t t = 0; t < rest_.size(); ++t)
    largest = std::max(largest, kernels_.element.green_strain(gradient(t)).norm());
  return largest;
}

void add_weight(FemBody& body, double gravity) { body.loads.col(1) -= gravity * body.masses; }

std::vector<int> free_coordinates(const FemBody& body) {
  std::vector<int> free;
  for (long i = 0; i < body.nodes(); ++i)
    for (int axis = 0; axis < 3; ++axis)
      if (body.filters[i](axis, axis) != 0) free.push_back(static_cast<int>(3 * i + axis));
  return free;
}

double load_residual(const FemBody& body) {
  NodeArray f;
  body.forces(f);
  double sum = 0;
  for (const int k : free_coordinates(body)) sum += f(k / 3, k % 3) * f(k / 3, k % 3);
  return std::sqrt(sum) / std::max(body.loads.norm(), 1e-300);
}

}  // namespace kit
