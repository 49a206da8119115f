#pragma once
// A cloth in motion (chapter 6): the state of a scene's sheet, one step of any of the four
// explicit integrators, then the contacts and Provot's strain limit. Only what the scene lists
// is built and computed (ClothWork counts it). The student's step (ex 6.3) and sphere response
// (ex 6.4) come in as function pointers, so the kit's system runs the student's code.
#include <cstdint>
#include <vector>

#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_forces.hpp>
#include <kit/cloth/cloth_scene.hpp>

namespace kit {

/// Ex 6.3's step for the kit's force pass, and ex 6.4's sphere response.
using SymplecticClothStep = void (*)(NodeArray& x, NodeArray& v, const Eigen::VectorXd& masses,
                                     const std::vector<std::int32_t>& pins, const ClothForces& forces,
                                     NodeArray& f, double dt);
using SphereResponse = long (*)(NodeArray& x, NodeArray& v, const SphereCollider& sphere);
using SpringBuilder = Springs (*)(const ClothGrid& grid, const SpringLayout& layout);
/// Ex 6.1's force on a spring's end a [N], from both ends' positions [m] and velocities [m/s], the
/// rest length [m] and the family's K and μ (chapter 6 checks it; chapter 9's springs model uses it).
using SpringForce = Vec3 (*)(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double rest,
                             const SpringFamily& family);
struct ClothKernels {
  SpringBuilder build_springs = nullptr;          ///< ex 6.2, for experiments that build many cloths
  SymplecticClothStep symplectic_step = nullptr;  ///< needed by ClothIntegrator::symplectic_euler
  SphereResponse collide_sphere = nullptr;        ///< needed when the scene has spheres
};

/// The radius at which the cloth meets `sphere` [m]: √(r² + d²/4), d a cell's diagonal, so that
/// an edge of unstretched length ≤ d between two nodes on it does not cut into the sphere.
double contact_radius(const ClothGrid& grid, const SphereCollider& sphere);

class ClothSystem {
 public:
  /// The scene's sheet at rest, with the given springs (ex 6.2 builds them). Throws
  /// std::invalid_argument when a kernel the scene needs is missing.
  ClothSystem(const ClothScene& scene, Springs springs, ClothKernels kernels);

  /// One step of dt [s], then the strain limit, the ground and the spheres, in that order. A
  /// sphere is met at contact_radius, so that the straight edges between nodes on it stay
  /// outside it too. Contacts never move a pinned node.
  void step(ClothIntegrator integrator, double dt);
  /// What follows every step, whatever moved x and v (chapter 7's implicit steps too): t += dt,
  /// then the strain limit, the ground and the spheres.
  void finish_step(double dt);

  NodeArray x, v;  ///< positions [m] and velocities [m/s], row i = node i
  double t = 0;    ///< [s]
  ClothWork work;

  const ClothScene& scene() const { return scene_; }
  const Springs& springs() const { return springs_; }
  const ClothForces& forces() const { return forces_; }
  const Eigen::VectorXd& masses() const { return forces_.masses(); }
  const std::vector<std::int32_t>& pins() const { return pins_; }
  /// 1/m per node [1/kg], 0 for a pinned node.
  const Eigen::VectorXd& inverse_masses() const { return inverse_mass_; }
  double kinetic() const { return kinetic_energy(masses(), v); }
  double potential() const { return forces_.potential_energy(x); }
  /// The largest relative stretch of the structural springs (or, without them, of any family).
  double max_strain() const;
  /// True once a position or velocity is not finite.
  bool blew_up() const { return !x.allFinite() || !v.allFinite(); }

 private:
  void accelerations(const NodeArray& pos, const NodeArray& vel, NodeArray& a);
  void contacts();
  void limit_strain(double dt);

  ClothScene scene_;
  Springs springs_;
  ClothForces forces_;
  ClothKernels kernels_;
  std::vector<std::int32_t> pins_;
  Eigen::VectorXd inverse_mass_;  ///< 0 for pinned nodes: they never accelerate
  NodeArray pinned_x_;            ///< the pins' positions, kept across the student's sphere response
  NodeArray f_, k1x_, k1v_, k2x_, k2v_, k3x_, k3v_, k4x_, k4v_, mid_x_, mid_v_;  ///< scratch
};

}  // namespace kit
