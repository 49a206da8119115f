#include <fmt/format.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <kit/fem_body.hpp>
#include <map>
#include <stdexcept>
#include <utility>

namespace kit {

const char* model_name(FemModel model) {
  switch (model) {
    case FemModel::linear:
      return "linear";
    case FemModel::stvk:
      return "stvk";
    case FemModel::springs:
      return "springs";
  }
  return "?";
}

namespace {

void require_positive(double value, const char* what) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument(fmt::format("{} {}: expected a positive finite number", what, value));
}

/// One spring per mesh edge, of stiffness E t ΣA / |e|² over the triangles beside it.
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

Vector3 node3(const NodeArray& x, int i) {
  return x.row(i).transpose();
}

}  // namespace

FemBody::FemBody(TriangleMesh mesh, const FemMaterial& material, FemModel model, const ContinuumKernels& kernels)
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
  filters.assign(n, Matrix3::Identity());
  rest_.reserve(mesh_.triangles.size());
  for (const auto& tri : mesh_.triangles) {
    rest_.push_back(rest_triangle(mesh_.nodes[tri[0]], mesh_.nodes[tri[1]], mesh_.nodes[tri[2]], material.thickness));
    for (const int node : tri) masses[node] += material.density * rest_.back().volume / 3;
  }
  if (model_ == FemModel::springs) springs_ = edge_springs(mesh_, material_);
  if (model_ == FemModel::linear)
    for (const auto& rest : rest_) linear_stiffness_.push_back(linear_stiffness(rest.inverse, rest.volume, lame_));
}

void FemBody::hold_in_plane() {
  for (auto& filter : filters) filter(2, 2) = 0;
}

void FemBody::forces(NodeArray& out, double drag) const {
  out = loads;
  if (drag != 0) out -= drag * (masses.asDiagonal() * v);
  if (model_ == FemModel::springs) {
    for (std::size_t s = 0; s < springs_.size(); ++s) {
      const int a = springs_.a[s], b = springs_.b[s];
      const Vector3 f = kernels_.spring_force(node3(x, a), node3(x, b), node3(v, a), node3(v, b), springs_.rest[s],
                                              SpringFamily{springs_.stiffness[s], 0.0});
      out.row(a) += f.transpose();
      out.row(b) -= f.transpose();
    }
    return;
  }
  for (std::size_t t = 0; t < rest_.size(); ++t) {
    const auto& tri = mesh_.triangles[t];
    const Matrix32 F =
        kernels_.element.deformation_gradient(node3(x, tri[0]), node3(x, tri[1]), node3(x, tri[2]), rest_[t].inverse);
    const ElementForces f = model_ == FemModel::stvk
                                ? kernels_.element.forces(F, rest_[t].inverse, rest_[t].volume, lame_)
                                : linear_forces(F, rest_[t].inverse, rest_[t].volume, lame_);
    for (int k = 0; k < 3; ++k) out.row(tri[k]) += f.col(k).transpose();
  }
}

void FemBody::stiffness(SparseMatrix& out) const {
  std::vector<Eigen::Triplet<double>> entries;
  const auto add_block = [&](int row_node, int column_node, const Matrix3& block) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) entries.emplace_back(3 * row_node + r, 3 * column_node + c, block(r, c));
  };
  if (model_ == FemModel::springs) {
    entries.reserve(springs_.size() * 36);
    for (std::size_t s = 0; s < springs_.size(); ++s) {
      const int a = springs_.a[s], b = springs_.b[s];
      const Matrix3 J =
          kernels_.spring_stiffness(node3(x, a), node3(x, b), springs_.rest[s], springs_.stiffness[s], false);
      add_block(a, a, J);
      add_block(b, b, J);
      add_block(a, b, -J);
      add_block(b, a, -J);
    }
  } else {
    entries.reserve(rest_.size() * 81);
    for (std::size_t t = 0; t < rest_.size(); ++t) {
      const auto& tri = mesh_.triangles[t];
      Matrix9 K;
      if (model_ == FemModel::stvk) {
        const Matrix32 F = kernels_.element.deformation_gradient(node3(x, tri[0]), node3(x, tri[1]), node3(x, tri[2]),
                                                                 rest_[t].inverse);
        K = kernels_.element.stiffness(F, rest_[t].inverse, rest_[t].volume, lame_);
      } else {
        K = linear_stiffness_[t];
      }
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) add_block(tri[a], tri[b], K.block<3, 3>(3 * a, 3 * b));
    }
  }
  out.resize(3 * nodes(), 3 * nodes());
  out.setFromTriplets(entries.begin(), entries.end());
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
    const auto& tri = mesh_.triangles[t];
    const Matrix32 F =
        kernels_.element.deformation_gradient(node3(x, tri[0]), node3(x, tri[1]), node3(x, tri[2]), rest_[t].inverse);
    if (model_ == FemModel::stvk) {
      // W = V (μ E:E + ½λ tr(E)²), with E from the student's ex 9.1.
      const Matrix2 E = kernels_.element.green_strain(F);
      energy += rest_[t].volume * (lame_.mu * E.squaredNorm() + 0.5 * lame_.lambda * E.trace() * E.trace());
    } else {
      const Matrix2 strain = cauchy_strain(F);
      const Matrix2 stress = lame_.lambda * strain.trace() * Matrix2::Identity() + 2 * lame_.mu * strain;
      energy += 0.5 * rest_[t].volume * (stress.array() * strain.array()).sum();
    }
  }
  return energy;
}

double FemBody::largest_green_strain() const {
  double largest = 0;
  for (std::size_t t = 0; t < rest_.size(); ++t) {
    const auto& tri = mesh_.triangles[t];
    const Matrix32 F =
        kernels_.element.deformation_gradient(node3(x, tri[0]), node3(x, tri[1]), node3(x, tri[2]), rest_[t].inverse);
    largest = std::max(largest, kernels_.element.green_strain(F).norm());
  }
  return largest;
}

void add_weight(FemBody& body, double gravity) {
  body.loads.col(1) -= gravity * body.masses;
}

namespace {

/// The free coordinates: those a filter's diagonal keeps (filters here are diagonal 0/1).
std::vector<int> free_coordinates(const FemBody& body) {
  std::vector<int> free;
  for (long i = 0; i < body.nodes(); ++i)
    for (int axis = 0; axis < 3; ++axis)
      if (body.filters[i](axis, axis) != 0) free.push_back(static_cast<int>(3 * i + axis));
  return free;
}

}  // namespace

namespace {

/// Newton's method at the body's present loads, from its present positions.
/// The rest positions in the plane, one row a node [m].
Eigen::MatrixX2d rest_positions(const FemBody& body) {
  Eigen::MatrixX2d rest(body.nodes(), 2);
  for (long i = 0; i < body.nodes(); ++i) rest.row(i) = body.mesh().nodes[i].transpose();
  return rest;
}

StaticSolve newton(FemBody& body, int max_iterations, double tolerance) {
  const std::vector<int> free = free_coordinates(body);
  std::vector<int> slot(3 * body.nodes(), -1);
  for (std::size_t k = 0; k < free.size(); ++k) slot[free[k]] = static_cast<int>(k);
  const double load = std::max(body.loads.norm(), 1e-300);
  StaticSolve out;
  NodeArray f;
  SparseMatrix K;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  double last_step = 0;  // the largest coordinate change of the last Newton step [m]
  for (;;) {
    body.forces(f);
    Eigen::VectorXd rhs(free.size());
    for (std::size_t k = 0; k < free.size(); ++k) rhs[k] = f(free[k] / 3, free[k] % 3);
    out.residual = rhs.norm() / load;
    // Converged, or at round-off. The element forces that cancel at equilibrium are up to 1e4
    // times the loads (a cantilever's root) and are computed from absolute positions, so their sum
    // has a floor that rises as the displacement shrinks against the body's size (a stiff
    // material). There the steps stop changing anything: the last moved no node by more than
    // 1e-9 of the largest displacement.
    const double displacement = (body.x.leftCols<2>() - rest_positions(body)).cwiseAbs().maxCoeff();
    if (out.residual <= tolerance || (out.iterations > 1 && last_step <= 1e-9 * displacement)) {
      out.converged = true;
      return out;
    }
    if (out.iterations == max_iterations) {
      out.failure = fmt::format("no convergence in {} Newton steps (residual {:.2g})", max_iterations, out.residual);
      return out;
    }
    body.stiffness(K);
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(K.nonZeros());
    for (int row = 0; row < K.outerSize(); ++row)
      for (SparseMatrix::InnerIterator it(K, row); it; ++it)
        if (slot[row] >= 0 && slot[it.col()] >= 0) entries.emplace_back(slot[row], slot[it.col()], -it.value());
    Eigen::SparseMatrix<double> reduced(static_cast<Eigen::Index>(free.size()), static_cast<Eigen::Index>(free.size()));
    reduced.setFromTriplets(entries.begin(), entries.end());
    solver.compute(reduced);
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

namespace {

/// Applies each node's filter to its three entries of the interleaved vector w.
void filter_in_place(const FemBody& body, Eigen::VectorXd& w) {
  for (long i = 0; i < body.nodes(); ++i) w.segment<3>(3 * i) = body.filters[i] * w.segment<3>(3 * i);
}

}  // namespace

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
  double omega_squared = 0;
  for (int row = 0; row < K.outerSize(); ++row) {
    const long node = row / 3;
    if (body.filters[node](row % 3, row % 3) == 0) continue;
    double sum = 0;
    for (SparseMatrix::InnerIterator it(K, row); it; ++it)
      if (body.filters[it.col() / 3](it.col() % 3, it.col() % 3) != 0) sum += std::abs(it.value());
    omega_squared = std::max(omega_squared, sum / body.masses[node]);
  }
  return 2 / std::sqrt(omega_squared);
}

ImplicitStep implicit_step(FemBody& body, double h, double drag, double tolerance, int max_iterations) {
  SparseMatrix K;
  body.stiffness(K);
  NodeArray f;
  body.forces(f, drag);
  const Eigen::VectorXd v = flatten(body.v);
  SparseMatrix A = (-h * h) * K;
  for (long i = 0; i < body.nodes(); ++i)
    for (int axis = 0; axis < 3; ++axis) A.coeffRef(3 * i + axis, 3 * i + axis) += body.masses[i] * (1 + h * drag);
  Eigen::VectorXd b = h * (flatten(f) + h * (K * v));
  filter_in_place(body, b);
  const PcgResult solve = body.kernels().pcg(A, b, body.filters, tolerance, max_iterations);
  unflatten(v + solve.x, body.v);
  body.x += h * body.v;
  return {solve.iterations, solve.converged};
}

}  // namespace kit
