#include <kit/ode/stability.hpp>

#include <stdexcept>

namespace kit {

double spectral_radius(const Mat2& m) {
  // Eigenvalues of [[a, b], [c, d]]: (tr ± sqrt(tr² − 4 det)) / 2.
  const std::complex<double> tr = m.trace(), det = m.determinant();
  const std::complex<double> root = std::sqrt(tr * tr - 4.0 * det);
  return std::max(std::abs((tr + root) / 2.0), std::abs((tr - root) / 2.0));
}

std::pair<std::complex<double>, std::complex<double>> oscillator_z(double h, double zeta) {
  const std::complex<double> root = std::sqrt(std::complex<double>(zeta * zeta - 1.0));
  return {h * (-zeta + root), h * (-zeta - root)};
}

double spectral_radius(const std::function<std::complex<double>(std::complex<double>)>& amplification,
                       double h, double zeta) {
  const auto [z1, z2] = oscillator_z(h, zeta);
  return std::max(std::abs(amplification(z1)), std::abs(amplification(z2)));
}

double stability_limit(const std::function<double(double)>& radius, double h_max, int samples,
                       double rel_tol) {
  // A tolerance of 1e-13 absorbs round-off in an exactly neutral radius (symplectic Euler's 1)
  // while still seeing weak growth such as midpoint RK2's (ωΔt)⁴/8 from ωΔt = 0.01 on.
  const auto unstable = [&](double h) { return !(radius(h) <= 1.0 + 1e-13); };
  const double h_min = 0.01;
  if (unstable(h_min)) return 0.0;
  double previous = h_min;
  for (int i = 1; i <= samples; ++i) {
    const double h = h_min * std::pow(h_max / h_min, double(i) / samples);
    if (unstable(h)) {
      double lo = previous, hi = h;
      while (hi - lo > rel_tol * hi) {
        const double mid = 0.5 * (lo + hi);
        (unstable(mid) ? hi : lo) = mid;
      }
      return 0.5 * (lo + hi);
    }
    previous = h;
  }
  return std::numeric_limits<double>::infinity();
}

double critical_step(const std::function<bool(double)>& unstable, double stable_dt, double unstable_dt,
                     double rel_tol) {
  if (unstable(stable_dt) || !unstable(unstable_dt))
    throw std::invalid_argument("critical_step needs a stable and an unstable step to bracket the limit");
  while (unstable_dt - stable_dt > rel_tol * unstable_dt) {
    const double mid = 0.5 * (stable_dt + unstable_dt);
    (unstable(mid) ? unstable_dt : stable_dt) = mid;
  }
  return 0.5 * (stable_dt + unstable_dt);
}

std::vector<std::array<double, 2>> level_set_points(const std::function<double(double, double)>& f,
                                                    double level, double x0, double x1, double y0, double y1,
                                                    int nx, int ny) {
  std::vector<double> grid(static_cast<std::size_t>((nx + 1) * (ny + 1)));
  const auto x = [&](int i) { return x0 + (x1 - x0) * i / nx; };
  const auto y = [&](int j) { return y0 + (y1 - y0) * j / ny; };
  const auto at = [&](int i, int j) -> double& { return grid[static_cast<std::size_t>(j * (nx + 1) + i)]; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) at(i, j) = f(x(i), y(j)) - level;
  std::vector<std::array<double, 2>> points;
  const auto crossing = [&](double a, double b) {
    return (a < 0) != (b < 0) && std::isfinite(a) && std::isfinite(b);
  };
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      if (i < nx && crossing(at(i, j), at(i + 1, j))) {
        const double s = at(i, j) / (at(i, j) - at(i + 1, j));
        points.push_back({x(i) + s * (x(i + 1) - x(i)), y(j)});
      }
      if (j < ny && crossing(at(i, j), at(i, j + 1))) {
        const double s = at(i, j) / (at(i, j) - at(i, j + 1));
        points.push_back({x(i), y(j) + s * (y(j + 1) - y(j))});
      }
    }
  }
  return points;
}

}  // namespace kit
