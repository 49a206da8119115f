#pragma once
// The orbit chapter 4 integrates, chosen by name (--problem), with the reference its errors are
// measured against: Arenstorf's orbit, which closes only to about 3e-8, against GSL rk8pd at
// rtol = atol = 1e-14; Kepler's orbit against its exact solution (adaptive_rk_models.hpp).
#include <functional>
#include <string>
#include <vector>

#include <kit/base/enum_names.hpp>
#include <kit/base/state.hpp>
#include <kit/problems/adaptive_rk_models.hpp>

namespace kit {

/// The orbits --problem chooses from.
enum class Orbit { arenstorf, kepler };
inline constexpr auto orbit_names = enum_names<Orbit>({
    {Orbit::arenstorf, "arenstorf", "Arenstorf orbit"},
    {Orbit::kepler, "kepler", "Kepler orbit"},
});
static_assert(orbit_names.in_order());

struct OrbitProblem {
  std::string name;                            ///< "arenstorf" or "kepler"
  std::string title;                           ///< "Arenstorf orbit", "Kepler orbit (e = 0.6)"
  std::function<Vec4(double, const Vec4&)> f;  ///< y' = f(t, y), y = (x, y, x', y')
  Vec4 y0;                                     ///< y(0)
  double t_end = 0;                            ///< T, one period, in the problem's time units
  Vec4 reference;                              ///< y(T): exact (Kepler) or GSL rk8pd at 1e-14 (Arenstorf)
  bool earth_and_moon = false;                 ///< true for Arenstorf: the figure marks both bodies
  std::string length_unit;                     ///< "Earth-Moon distances", "semi-major axes"
  std::string time_unit;                       ///< "months/2π", "periods/2π"
  /// The path at t = T·i/n, i = 1 … n, from GSL rk8pd at 1e-14, for figures.
  Trajectory<Vec4> path(int n) const;
};

/// Arenstorf's orbit, or Kepler's with eccentricity e in [0, 1) (unused for Arenstorf).
OrbitProblem orbit_problem(Orbit orbit, double eccentricity);

}  // namespace kit
