#pragma once
// The cloth's force pass (lecture, "Simulation de tissus"): for every spring s = (a, b), with
// x = x_a − x_b, l = |x| and x̂ = x/l,
//   f_a = [K (L0 − l) − μ (v_a − v_b)·x̂] x̂,   f_b = −f_a          [N]
// (Hooke along the spring, damping on the rate of change of its length only), plus gravity m·g
// (ERRATA item 13: the lecture's "+ g" is an acceleration) and linear air drag −m·c·v when the
// scene has them. Only what the scene lists is computed; counters prove it.
#include <cstdint>
#include <optional>
#include <vector>

#include <kit/cloth/cloth.hpp>

namespace kit {

/// What a run computed, counted (tests check these, never times).
struct ClothWork {
  long force_passes = 0;                     ///< whole-cloth force evaluations
  long spring_terms = 0;                     ///< spring forces evaluated, all families
  long spring_terms_by_kind[3] = {0, 0, 0};  ///< per SpringKind
  long gravity_terms = 0;                    ///< node gravity forces added
  long drag_terms = 0;                       ///< node drag forces added
  long sphere_tests = 0;                     ///< node-sphere tests
  long ground_tests = 0;                     ///< node-ground tests
  long contacts = 0;                         ///< nodes pushed out of a collider
  long strain_passes = 0;                    ///< Provot passes over the springs
  long strain_corrections = 0;               ///< springs pulled back
};

/// The production force pass. Springs are regrouped once into runs that share the node offset
/// d = b − a, with a consecutive along the run (a grid's rows), so that the inner loop reads
/// and writes contiguous memory and vectorises; the regrouping keeps every spring.
class ClothForces {
 public:
  ClothForces(const Springs& springs, const Eigen::VectorXd& masses, std::optional<Vec3> gravity,
              std::optional<double> drag);

  /// f = the total force on every node [N], for positions x [m] and velocities v [m/s].
  void operator()(const NodeArray& x, const NodeArray& v, NodeArray& f) const;
  /// Spring energy ½K(l − L0)² summed, plus −m g·x when there is gravity [J].
  double potential_energy(const NodeArray& x) const;
  /// Counters go here when set (nullptr: not counted).
  void count_into(ClothWork* work) const { work_ = work; }

  long nodes() const { return long(masses_.size()); }
  std::size_t springs() const { return rest_.size(); }
  const Eigen::VectorXd& masses() const { return masses_; }

 private:
  struct Run {
    std::int32_t first_node;  ///< a of the run's first spring
    std::int32_t offset;      ///< d = b − a, the same along the run
    std::int32_t first;       ///< index of the run's first spring in the arrays below
    std::int32_t length;
  };
  std::vector<Run> runs_;
  std::vector<double> rest_, stiffness_, damping_;  ///< per spring, in run order
  long by_kind_[3] = {0, 0, 0};
  bool damped_ = false;
  Eigen::VectorXd masses_;
  std::optional<Vec3> gravity_;
  std::optional<double> drag_;
  mutable std::vector<double> fx_, fy_, fz_;  ///< one run's spring forces, before they scatter
  mutable ClothWork* work_ = nullptr;
};

/// The kinetic energy ½ Σ m |v|² [J].
double kinetic_energy(const Eigen::VectorXd& masses, const NodeArray& v);

/// The largest relative stretch (l − L0)/L0 over the springs of one family (0 if it has none);
/// negative when every spring is compressed.
double max_strain(const Springs& springs, const NodeArray& x, SpringKind kind);

}  // namespace kit
