// A cloth in motion (cloth_system.hpp).
#include <kit/cloth/cloth_system.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace kit {

ClothSystem::ClothSystem(const ClothScene& scene, Springs springs, ClothKernels kernels)
    : scene_(scene),
      springs_(std::move(springs)),
      forces_(springs_, scene.grid.node_masses(), scene.gravity, scene.drag),
      kernels_(kernels) {
  x = scene.grid.rest_positions();
  v = NodeArray::Zero(x.rows(), 3);
  inverse_mass_ = masses().cwiseInverse();
  for (const Pin& pin : scene.pins) {
    const auto node = std::int32_t(pinned_node(scene.grid, pin));
    if (std::find(pins_.begin(), pins_.end(), node) == pins_.end()) pins_.push_back(node);
    inverse_mass_[node] = 0;
  }
  pinned_x_.resize(long(pins_.size()), 3);
  if (!scene.spheres.empty() && !kernels.collide_sphere)
    throw std::invalid_argument("the scene has spheres but no sphere response was given");
  forces_.count_into(&work);
}

void ClothSystem::accelerations(const NodeArray& pos, const NodeArray& vel, NodeArray& a) {
  forces_(pos, vel, a);
  for (int axis = 0; axis < 3; ++axis) a.col(axis).array() *= inverse_mass_.array();
}

void ClothSystem::step(ClothIntegrator integrator, double dt) {
  switch (integrator) {
    case ClothIntegrator::explicit_euler:  // chapter 1: both updates from the old state
      accelerations(x, v, k1v_);
      x += dt * v;
      v += dt * k1v_;
      break;
    case ClothIntegrator::symplectic_euler:  // ex 6.3: v first, then x with the new v
      if (!kernels_.symplectic_step) throw std::invalid_argument("no symplectic step was given");
      kernels_.symplectic_step(x, v, masses(), pins_, forces_, f_, dt);
      break;
    case ClothIntegrator::midpoint:  // chapter 3: the slope at the half step, from Euler's half step
      accelerations(x, v, k1v_);
      mid_x_ = x + 0.5 * dt * v;
      mid_v_ = v + 0.5 * dt * k1v_;
      accelerations(mid_x_, mid_v_, k2v_);
      x += dt * mid_v_;
      v += dt * k2v_;
      break;
    case ClothIntegrator::rk4:  // chapter 3: slopes at t, twice at t + dt/2, and at t + dt
      accelerations(x, v, k1v_);
      mid_x_ = x + 0.5 * dt * v, mid_v_ = v + 0.5 * dt * k1v_;
      k2x_ = mid_v_;
      accelerations(mid_x_, mid_v_, k2v_);
      mid_x_ = x + 0.5 * dt * k2x_, mid_v_ = v + 0.5 * dt * k2v_;
      k3x_ = mid_v_;
      accelerations(mid_x_, mid_v_, k3v_);
      mid_x_ = x + dt * k3x_, mid_v_ = v + dt * k3v_;
      k4x_ = mid_v_;
      accelerations(mid_x_, mid_v_, k4v_);
      x += dt / 6 * (v + 2 * k2x_ + 2 * k3x_ + k4x_);
      v += dt / 6 * (k1v_ + 2 * k2v_ + 2 * k3v_ + k4v_);
      break;
  }
  finish_step(dt);
}

void ClothSystem::finish_step(double dt) {
  t += dt;
  // The strain limit first: it moves nodes, and the contacts after it are the last word, so no
  // node ends a step inside a collider.
  if (scene_.strain_limit) limit_strain(dt);
  contacts();
}

double contact_radius(const ClothGrid& grid, const SphereCollider& sphere) {
  // Nodes at radius R joined by an edge of length d (at most a cell's diagonal, unstretched)
  // keep the edge's midpoint at √(R² − d²/4) from the centre: R = √(r² + d²/4) keeps the whole
  // edge out of the sphere of radius r. The padding R − r never exceeds d/2.
  const double diagonal2 = grid.dx() * grid.dx() + grid.dy() * grid.dy();
  return std::sqrt(sphere.radius * sphere.radius + diagonal2 / 4);
}

void ClothSystem::contacts() {
  if (scene_.ground) {
    // The ground's contact: the same response as a sphere's (ex 6.4) with the constant normal +y.
    const GroundCollider& ground = *scene_.ground;
    work.ground_tests += x.rows();
    for (Eigen::Index i = 0; i < x.rows(); ++i) {
      if (!(x(i, 1) < ground.height) || inverse_mass_[i] == 0) continue;  // a pin stays where it is
      ++work.contacts;
      x(i, 1) = ground.height;
      const double vn = v(i, 1);
      if (vn >= 0) continue;
      v(i, 1) = 0;
      const double speed = std::hypot(v(i, 0), v(i, 2)), loss = ground.friction * -vn;
      const double keep = speed > loss ? 1 - loss / speed : 0.0;
      v(i, 0) *= keep, v(i, 2) *= keep;
    }
  }
  for (const SphereCollider& sphere : scene_.spheres) {
    SphereCollider padded = sphere;
    padded.radius = contact_radius(scene_.grid, sphere);
    work.sphere_tests += x.rows();
    // Ex 6.4 sees every node; a pin it moved goes back where it is held.
    for (std::size_t k = 0; k < pins_.size(); ++k) pinned_x_.row(long(k)) = x.row(pins_[k]);
    work.contacts += kernels_.collide_sphere(x, v, padded);
    for (std::size_t k = 0; k < pins_.size(); ++k)
      x.row(pins_[k]) = pinned_x_.row(long(k)), v.row(pins_[k]).setZero();
  }
}

void ClothSystem::limit_strain(double dt) {
  // Provot 1995: a structural or shear spring longer than (1 + ε_max) L0 is shortened to that
  // length, each free end moving half the excess along the spring (a pinned end does not move,
  // its partner moves all of it). Velocities change by the same displacement / dt, so the next
  // step does not undo the correction.
  const StrainLimit& limit = *scene_.strain_limit;
  for (int pass = 0; pass < limit.iterations; ++pass) {
    ++work.strain_passes;
    long corrected = 0;
    for (std::size_t s = 0; s < springs_.size(); ++s) {
      if (springs_.kind[s] == SpringKind::bend) continue;
      const auto a = springs_.a[s], b = springs_.b[s];
      const Vec3 d = x.row(a) - x.row(b);
      const double l = d.norm(), longest = (1 + limit.max_strain) * springs_.rest[s];
      if (!(l > longest)) continue;
      const double wa = inverse_mass_[a] > 0, wb = inverse_mass_[b] > 0;
      if (wa + wb == 0) continue;
      const Vec3 shift = (l - longest) / (wa + wb) * d / l;
      x.row(a) -= wa * shift.transpose(), v.row(a) -= wa / dt * shift.transpose();
      x.row(b) += wb * shift.transpose(), v.row(b) += wb / dt * shift.transpose();
      ++corrected;
    }
    work.strain_corrections += corrected;
    if (corrected == 0) break;
  }
}

double ClothSystem::max_strain() const {
  const SpringKind kind = springs_.count(SpringKind::structural) > 0 ? SpringKind::structural
                          : springs_.count(SpringKind::shear) > 0    ? SpringKind::shear
                                                                     : SpringKind::bend;
  return kit::max_strain(springs_, x, kind);
}

}  // namespace kit
