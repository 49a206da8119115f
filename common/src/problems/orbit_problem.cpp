#include <kit/problems/orbit_problem.hpp>

#include <cmath>

#include <fmt/format.h>

#include <kit/ode/reference_solver.hpp>

namespace kit {

namespace {
GslOptions tight() {
  GslOptions options;  // rk8pd
  options.rtol = options.atol = 1e-14;
  return options;
}
}  // namespace

Trajectory<Vec4> OrbitProblem::path(int n) const {
  std::vector<double> times;
  for (int i = 1; i <= n; ++i) times.push_back(t_end * i / n);
  return reference_solution(f, 0.0, y0, times, tight());
}

OrbitProblem orbit_problem(Orbit orbit, double eccentricity) {
  OrbitProblem p;
  p.name = orbit_names.flag(orbit);
  switch (orbit) {
    case Orbit::arenstorf:
      p.title = orbit_names.display(orbit);
      p.f = Arenstorf{};
      p.y0 = Arenstorf::initial_state();
      p.t_end = Arenstorf::period;
      p.reference = reference_solution(p.f, 0.0, p.y0, {p.t_end}, tight()).u.back();
      p.earth_and_moon = true;
      p.length_unit = "Earth-Moon distances", p.time_unit = "months/2π";
      break;
    case Orbit::kepler: {
      const Kepler kepler{eccentricity};
      p.title = fmt::format("{} (e = {})", orbit_names.display(orbit), eccentricity);
      p.f = kepler;
      p.y0 = kepler.initial_state();
      p.t_end = 2 * M_PI;
      p.reference = kepler.exact(p.t_end);
      p.length_unit = "semi-major axes", p.time_unit = "periods/2π";
      break;
    }
  }
  return p;
}

}  // namespace kit
