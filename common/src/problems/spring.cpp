#include <kit/problems/spring.hpp>

#include <cmath>

namespace kit {

double Spring::omega() const { return std::sqrt(stiffness / mass); }

double Spring::damping_ratio() const { return damping / (2.0 * std::sqrt(stiffness * mass)); }

double Spring::energy(const Vec2& u) const {
  const double stretch = u[0] - rest_length;
  return 0.5 * mass * u[1] * u[1] + 0.5 * stiffness * stretch * stretch;
}

std::pair<std::complex<double>, std::complex<double>> Spring::eigenvalues() const {
  const double w = omega(), zeta = damping_ratio();
  const std::complex<double> root = std::sqrt(std::complex<double>(zeta * zeta - 1.0));
  return {w * (-zeta + root), w * (-zeta - root)};
}

Vec2 spring_motion(const Spring& spring, const Vec2& u0, double t) {
  // y = x − L0 obeys y'' + 2ζω y' + ω² y = 0 with y(0) = y0, y'(0) = v0.
  const double w = spring.omega(), zeta = spring.damping_ratio();
  const double y0 = u0[0] - spring.rest_length, v0 = u0[1];
  double y = 0, v = 0;
  if (zeta < 1.0) {
    // Under- or undamped: y = e^{−ζωt} (y0 cos ω_d t + (v0 + ζω y0)/ω_d sin ω_d t).
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    const double c = y0, s = (v0 + zeta * w * y0) / wd;
    const double decay = std::exp(-zeta * w * t), cos_t = std::cos(wd * t), sin_t = std::sin(wd * t);
    y = decay * (c * cos_t + s * sin_t);
    v = decay * ((-zeta * w) * (c * cos_t + s * sin_t) + wd * (-c * sin_t + s * cos_t));
  } else if (zeta == 1.0) {
    // Critical: y = (y0 + (v0 + ω y0) t) e^{−ωt}.
    const double slope = v0 + w * y0, decay = std::exp(-w * t);
    y = (y0 + slope * t) * decay;
    v = (slope - w * (y0 + slope * t)) * decay;
  } else {
    // Overdamped: y = e^{−ζωt} (y0 cosh βt + (v0 + ζω y0) sinh(βt)/β), β = ω sqrt(ζ² − 1).
    // This form has no cancellation as ζ → 1 (β → 0), where a e^{r1 t} + b e^{r2 t} has.
    const double beta = w * std::sqrt(zeta * zeta - 1.0), p = v0 + zeta * w * y0;
    if (beta * t < 30.0) {
      const double decay = std::exp(-zeta * w * t), ch = std::cosh(beta * t), sh = std::sinh(beta * t);
      y = decay * (y0 * ch + p * sh / beta);
      v = decay * (-zeta * w * (y0 * ch + p * sh / beta) + y0 * beta * sh + p * ch);
    } else {  // e^{r2 t} is negligible against e^{r1 t}; avoid cosh overflowing against decay
      const double r1 = -zeta * w + beta, e1 = 0.5 * std::exp(r1 * t);
      y = e1 * (y0 + p / beta);
      v = r1 * y;
    }
  }
  return {spring.rest_length + y, v};
}

}  // namespace kit
