#include <kit/problems/orbit_problem.hpp>

#include <cmath>
#include <stdexcept>

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

OrbitProblem orbit_problem(const std::string& name, double eccentricity) {
  OrbitProblem p;
  p.name = name;
  if (name == "arenstorf") {
    p.title = "Arenstorf orbit";
    p.f = Arenstorf{};
    p.y0 = Arenstorf::initial_state();
    p.t_end = Arenstorf::period;
    p.reference = reference_solution(p.f, 0.0, p.y0, {p.t_end}, tight()).u.back();
    p.earth_and_moon = true;
    p.length_unit = "Earth-Moon distances", p.time_unit = "months/2π";
  } else if (name == "kepler") {
    const Kepler kepler{eccentricity};
    p.title = fmt::format("Kepler orbit (e = {})", eccentricity);
    p.f = kepler;
    p.y0 = kepler.initial_state();
    p.t_end = 2 * M_PI;
    p.reference = kepler.exact(p.t_end);
    p.length_unit = "semi-major axes", p.time_unit = "periods/2π";
  } else {
    throw std::invalid_argument("unknown orbit problem: " + name);
  }
  return p;
}

}  // namespace kit
