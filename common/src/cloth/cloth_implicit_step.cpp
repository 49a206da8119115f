// Chapter 7's implicit steps (cloth_implicit_step.hpp).
#include <kit/cloth/cloth_implicit_step.hpp>

#include <algorithm>

#include <fmt/format.h>
#include <Eigen/IterativeLinearSolvers>

#include <kit/cloth/cloth_liu.hpp>

namespace kit {

ImplicitWork& ImplicitWork::operator+=(const ImplicitWork& o) {
  steps += o.steps, solves += o.solves, cg_iterations += o.cg_iterations;
  max_cg_iterations = std::max(max_cg_iterations, o.max_cg_iterations);
  unconverged_solves += o.unconverged_solves, newton_iterations += o.newton_iterations;
  newton_unconverged += o.newton_unconverged, local_global += o.local_global;
  factorizations += o.factorizations, multigrid_setups += o.multigrid_setups, blocks += o.blocks,
      assemblies += o.assemblies;
  filtered_nodes += o.filtered_nodes, worst_residual = std::max(worst_residual, o.worst_residual);
  return *this;
}

BackwardEulerStepper::BackwardEulerStepper(const ClothSystem& cloth, ImplicitMethod method,
                                           const ImplicitSettings& settings, ImplicitKernels kernels)
    : method_(method),
      settings_(settings),
      kernels_(kernels),
      matrix_(cloth.springs(), cloth.x.rows(), cloth.pins()),
      stiffness_(cloth.springs().size()),
      filters_(std::size_t(cloth.x.rows()), Mat3::Identity()) {
  if (method == ImplicitMethod::liu) throw std::invalid_argument("Liu et al.'s method has its own stepper");
  if (!kernels.stiffness_block) throw std::invalid_argument("no spring stiffness block (ex 7.1) was given");
  if (settings.solver == ImplicitSolver::pcg && !kernels.pcg)
    throw std::invalid_argument("no filtered PCG (ex 7.3) was given");
  if (settings.solver == ImplicitSolver::mg)
    multigrid_.emplace(cloth.scene().grid.nx, cloth.scene().grid.ny, matrix_.matrix);
}

void BackwardEulerStepper::jacobian(const ClothSystem& cloth, const NodeArray& x) {
  const Springs& springs = cloth.springs();
  for (std::size_t s = 0; s < springs.size(); ++s)
    stiffness_[s] = kernels_.stiffness_block(x.row(springs.a[s]), x.row(springs.b[s]), springs.rest[s],
                                             springs.stiffness[s], settings_.clamp);
  work.blocks += long(springs.size());
}

void BackwardEulerStepper::set_filters(const ClothSystem& cloth, const NodeArray& f) {
  // Baraff & Witkin §5.3: a pinned node has no free direction (S = 0); a node resting on a
  // collider and pressed into it moves only along its surface (S = I − nnᵀ, n the outward
  // normal) inside the solve, so the step itself cannot push it in. A node the forces pull off
  // is free again. "Resting" allows 1% of a sphere's radius: a step along the surface ends a
  // little outside a sphere, (h v)²/2R.
  std::fill(filters_.begin(), filters_.end(), Mat3::Identity());
  holds_.clear();
  const auto hold = [&](Eigen::Index i, const Vec3& n, double friction) {
    // S stays a projector when a node meets two colliders: only the part of n still free is
    // removed (Gram–Schmidt on the normals).
    Mat3& filter = filters_[std::size_t(i)];
    Vec3 u = filter * n;
    if (u.norm() < 1e-9) return;
    u.normalize();
    filter -= u * u.transpose();
    holds_.push_back({std::int32_t(i), u, friction, std::max(0.0, -f.row(i).dot(n))});
    ++work.filtered_nodes;
  };
  if (const auto& ground = cloth.scene().ground)
    for (Eigen::Index i = 0; i < cloth.x.rows(); ++i)
      if (cloth.x(i, 1) <= ground->height && f(i, 1) <= 0) hold(i, Vec3::UnitY(), ground->friction);
  for (const SphereCollider& sphere : cloth.scene().spheres) {
    const double radius = contact_radius(cloth.scene().grid, sphere);
    for (Eigen::Index i = 0; i < cloth.x.rows(); ++i) {
      const Vec3 r = cloth.x.row(i).transpose() - sphere.center;
      const double d = r.norm();
      if (d > 0 && d <= 1.01 * radius && f.row(i).dot(r) <= 0) hold(i, r / d, sphere.friction);
    }
  }
  for (const std::int32_t p : cloth.pins()) filters_[std::size_t(p)].setZero();
}

void BackwardEulerStepper::friction(ClothSystem& cloth, double h) const {
  // Coulomb friction on the nodes held on a collider during the step: the normal force N that
  // pressed them in, over h, takes up to μ h N / m off the tangential speed (never reversing it).
  for (const Hold& held : holds_) {
    if (held.friction == 0 || cloth.inverse_masses()[held.node] == 0) continue;
    Vec3 v = cloth.v.row(held.node);
    const Vec3 tangential = v - v.dot(held.normal) * held.normal;
    const double speed = tangential.norm(),
                 loss = held.friction * h * held.pressure * cloth.inverse_masses()[held.node];
    if (speed == 0) continue;
    v -= std::min(1.0, loss / speed) * tangential;
    cloth.v.row(held.node) = v;
  }
}

void BackwardEulerStepper::filter(Eigen::VectorXd& w) const {
  for (std::size_t i = 0; i < filters_.size(); ++i) {
    const auto first = 3 * Eigen::Index(i);
    w.segment<3>(first) = filters_[i] * w.segment<3>(first);
  }
}

Eigen::VectorXd BackwardEulerStepper::solve(Eigen::VectorXd b, double tolerance) {
  ++work.solves;
  PcgResult r;
  if (settings_.solver == ImplicitSolver::pcg) {
    r = kernels_.pcg(matrix_.matrix, b, filters_, tolerance, settings_.max_cg_iterations);
  } else if (settings_.solver == ImplicitSolver::mg) {
    // Pins eliminated as well as filtered: the multigrid's coarse grids then never move them.
    matrix_.constrain(b);
    ++work.multigrid_setups;
    if (!multigrid_->setup(matrix_.matrix))
      throw SolveFailed("A is not positive definite: the multigrid's coarsest Cholesky factorisation or a "
                        "diagonal block's inverse failed");
    r = multigrid_pcg(matrix_.matrix, b, filters_, *multigrid_, tolerance, settings_.max_cg_iterations);
  } else {
    matrix_.constrain(b);
    Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg;
    cg.setTolerance(tolerance);
    cg.setMaxIterations(settings_.max_cg_iterations);
    cg.compute(matrix_.matrix);
    r.x = cg.solve(b);
    r.iterations = int(cg.iterations());
    r.residual = cg.error();
    r.converged = cg.info() == Eigen::Success;
  }
  work.cg_iterations += r.iterations;
  work.max_cg_iterations = std::max(work.max_cg_iterations, long(r.iterations));
  if (!r.converged) ++work.unconverged_solves;
  work.worst_residual = std::max(work.worst_residual, r.residual);
  if (r.negative_curvature)
    throw SolveFailed(fmt::format("negative curvature (cᵀAc ≤ 0) at CG iteration {}: A is not positive "
                                  "definite",
                                  r.iterations));
  if (!r.x.allFinite() || !(r.residual <= 1))
    throw SolveFailed(fmt::format("the linear solve diverged: relative residual {:.3g} after {} iterations",
                                  r.residual, r.iterations));
  return r.x;
}

NodeArray BackwardEulerStepper::velocity_change(ClothSystem& cloth, double h) {
  const Springs& springs = cloth.springs();
  jacobian(cloth, cloth.x);
  cloth.forces()(cloth.x, cloth.v, f_);
  matrix_.assemble(springs, cloth.x, stiffness_, cloth.masses(), cloth.scene().drag, h);
  ++work.assemblies;
  // b = h (f_n + h ∂f/∂x v_n)   (ERRATA 14, the symmetric form)
  const double f_norm = f_.norm();
  Eigen::VectorXd b;
  stiffness_times(springs, stiffness_, cloth.v, b);
  b = h * (flatten(f_) + h * b);
  Eigen::VectorXd dv;
  if (filtered(settings_.solver)) {
    // Baraff & Witkin's z: a held node's velocity into or out of its collider is cancelled by
    // the step (Δv = z there), the solve finding the rest: A (z + y) = b with y = S y.
    set_filters(cloth, f_);
    const Eigen::VectorXd v = flatten(cloth.v);
    Eigen::VectorXd z = v;
    filter(z);
    z -= v;  // z = −(I − S) v
    dv = z + solve(b - matrix_.matrix * z, settings_.cg_tolerance);
  } else {
    dv = solve(b, settings_.cg_tolerance);
  }
  last_newton_residual = 0;
  if (method_ == ImplicitMethod::newton) dv = newton(cloth, std::move(dv), f_norm, h);
  NodeArray out;
  unflatten(dv, out);
  return out;
}

Eigen::VectorXd BackwardEulerStepper::newton(ClothSystem& cloth, Eigen::VectorXd dv, double f_norm,
                                             double h) {
  const Springs& springs = cloth.springs();
  const Eigen::VectorXd& m = cloth.masses();
  const bool filtered = kit::filtered(settings_.solver);
  ++work.newton_iterations;  // the linearised step was the first
  // g(Δv) = M Δv − h f(x_n + h (v_n + Δv), v_n + Δv), over the free directions only.
  Eigen::VectorXd g(dv.size());
  const auto residual = [&] {
    NodeArray dv_nodes;
    unflatten(dv, dv_nodes);
    v1_ = cloth.v + dv_nodes;
    x1_ = cloth.x + h * v1_;
    cloth.forces()(x1_, v1_, f_);
    g = -h * flatten(f_);
    for (Eigen::Index i = 0; i < m.size(); ++i) g.segment<3>(3 * i) += m[i] * dv.segment<3>(3 * i);
    if (filtered)
      filter(g);
    else
      for (const std::int32_t p : cloth.pins()) g.segment<3>(3 * p).setZero();
    return g.norm();
  };
  // ‖h f_n‖, unfiltered: it does not vanish when every node is held (a sheet at rest on the
  // ground is still pressed into it), unlike the filtered residual it is compared with.
  const double scale = std::max(h * f_norm, 1e-300);
  last_newton_residual = residual() / scale;
  for (int k = 1; k < settings_.iterations && last_newton_residual > settings_.newton_tolerance; ++k) {
    jacobian(cloth, x1_);
    matrix_.assemble(springs, x1_, stiffness_, m, cloth.scene().drag, h);
    ++work.assemblies;
    // Each correction solved to --cg-tol of the residual: the iterations converge at that rate
    // or faster (the clamped Jacobian is not exact under compression: not quadratically).
    dv += solve(-g, settings_.cg_tolerance);
    ++work.newton_iterations;
    last_newton_residual = residual() / scale;
  }
  if (last_newton_residual > settings_.newton_tolerance) ++work.newton_unconverged;
  return dv;
}

void BackwardEulerStepper::step(ClothSystem& cloth, double h) {
  const NodeArray dv = velocity_change(cloth, h);
  cloth.v += dv;
  friction(cloth, h);
  cloth.x += h * cloth.v;
  ++work.steps;
  cloth.finish_step(h);
}

std::unique_ptr<ImplicitStepper> make_implicit_stepper(const ClothSystem& cloth, ImplicitMethod method,
                                                       const ImplicitSettings& settings,
                                                       ImplicitKernels kernels) {
  if (method == ImplicitMethod::liu) return std::make_unique<LiuStepper>(cloth, settings.iterations);
  return std::make_unique<BackwardEulerStepper>(cloth, method, settings, kernels);
}

}  // namespace kit
