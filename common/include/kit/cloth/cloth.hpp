#pragma once
// The mass-spring cloth of chapters 6 and 7 (lecture, "Simulation de tissus"): a regular grid of
// nodes joined by springs of three families. Node data are contiguous arrays; the spring list is
// a struct of arrays. A family the scene does not ask for has no spring at all.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <kit/base/enum_names.hpp>
#include <kit/base/vec3.hpp>

namespace kit {

/// Per-node 3-vectors, one column per axis: x, y and z of all nodes are each contiguous (a
/// struct of arrays that Eigen also sees as an N×3 matrix). Row i is node i. Units follow use:
/// positions [m], velocities [m/s], forces [N].
using NodeArray = Eigen::Matrix<double, Eigen::Dynamic, 3>;
using Vector3 =
    Vec3;  ///< the name before kit/base/vec3.hpp: kept one release for exercise copies that use it

/// The three spring families of the lecture (Provot 1995).
enum class SpringKind : std::uint8_t {
  structural,  ///< the 4 direct neighbours: (i±1, j), (i, j±1)
  shear,       ///< the 4 diagonal neighbours: (i±1, j±1)
  bend,        ///< two steps away: (i±2, j), (i, j±2), and with BendLayout::eight also (i±2, j±2)
};
/// Their names, in scene files ([springs.shear]), summaries and tables.
inline constexpr auto spring_kind_names = enum_names<SpringKind>({
    {SpringKind::structural, "structural", "structural"},
    {SpringKind::shear, "shear", "shear"},
    {SpringKind::bend, "bend", "bend"},
});
static_assert(spring_kind_names.in_order());
inline constexpr auto all_spring_kinds = spring_kind_names.all();
inline const char* spring_kind_name(SpringKind kind) { return spring_kind_names.flag(kind); }

/// ERRATA item 12: the lecture's "8 voisins (bend)". Provot's layout joins each node to the 4
/// nodes two steps away along the axes; `eight` adds the 4 two-step diagonals.
enum class BendLayout : std::uint8_t { four, eight };

/// One family's springs: stiffness K [N/m] and damping μ [N·s/m], the damping acting along the
/// spring only (on the rate of change of its length), so a sheet falling as a whole is not slowed.
struct SpringFamily {
  double stiffness = 0;
  double damping = 0;
};

/// What springs a cloth has: each family present only if asked for.
struct SpringLayout {
  std::optional<SpringFamily> structural, shear, bend;
  BendLayout bend_layout = BendLayout::four;
  const std::optional<SpringFamily>& family(SpringKind kind) const;
};

/// A regular grid of nx × ny nodes spanning a physical rectangle: node (i, j), with i in [0, nx)
/// and j in [0, ny), rests at origin + i·dx·u + j·dy·v, where dx = width/(nx − 1), dy =
/// height/(ny − 1), and u, v are unit, orthogonal directions. Node index = j·nx + i.
struct ClothGrid {
  int nx = 2, ny = 2;
  double width = 1, height = 1;  ///< [m]
  Vec3 origin{0, 0, 0};          ///< node (0, 0) [m]
  Vec3 u{1, 0, 0}, v{0, 0, 1};
  double areal_density = 0.1;  ///< [kg/m²]

  long nodes() const { return long(nx) * ny; }
  long index(int i, int j) const { return long(j) * nx + i; }
  double dx() const { return width / (nx - 1); }
  double dy() const { return height / (ny - 1); }
  Vec3 rest_position(int i, int j) const { return origin + i * dx() * u + j * dy() * v; }
  /// The nodes at rest, row i = node i.
  NodeArray rest_positions() const;
  /// Node masses [kg]: the sheet's mass ρ·width·height shared by area, a node owning the part of
  /// the sheet nearer to it than to any other node (a corner a quarter cell, an edge node half).
  Eigen::VectorXd node_masses() const;
};

/// The spring list as a struct of arrays: spring s joins nodes a[s] and b[s], rests at
/// rest[s] [m], and has stiffness[s] [N/m] and damping[s] [N·s/m].
struct Springs {
  std::vector<std::int32_t> a, b;
  std::vector<double> rest, stiffness, damping;
  std::vector<SpringKind> kind;

  std::size_t size() const { return a.size(); }
  void reserve(std::size_t n);
  void add(long node_a, long node_b, double rest_length, const SpringFamily& family, SpringKind k);
  /// How many springs of this family.
  long count(SpringKind k) const;
};

/// How many springs a layout puts on an nx × ny grid, without building them (for estimates and
/// to check the network of ex 6.2, which builds them).
long spring_count(int nx, int ny, const SpringLayout& layout);

}  // namespace kit
