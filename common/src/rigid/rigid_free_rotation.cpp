#include <kit/rigid/rigid_free_rotation.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>

namespace kit {
namespace {

// λ and k² of Landau & Lifshitz §37, the moments taken as (a, b, c) = (I1, I2, I3) when M² > 2E I2
// and (I3, I2, I1) otherwise: both cases are one formula with the outer moments exchanged.
std::pair<double, double> rate_and_modulus_squared(const FreeRotation& motion) {
  double a = motion.moments[0], c = motion.moments[2];
  const double b = motion.moments[1], two_e = 2 * motion.energy, m2 = motion.momentum * motion.momentum;
  if (!motion.about_largest_axis()) std::swap(a, c);
  const double lambda = std::sqrt((c - b) * (m2 - two_e * a) / (a * b * c));
  const double k2 = (b - a) * (two_e * c - m2) / ((c - b) * (m2 - two_e * a));
  return {lambda, k2};
}

}  // namespace

bool FreeRotation::about_largest_axis() const { return momentum * momentum > 2 * energy * moments[1]; }

double FreeRotation::modulus() const {
  const double k2 = rate_and_modulus_squared(*this).second;
  return std::sqrt(std::clamp(k2, 0.0, 1.0));
}

double FreeRotation::period() const {
  const auto [lambda, k2] = rate_and_modulus_squared(*this);
  if (!(k2 < 1) || !(lambda > 0)) return std::numeric_limits<double>::infinity();
  gsl_sf_result K;
  gsl_set_error_handler_off();  // a failure is a status, never abort()
  // GSL takes the modulus k, not k².
  if (gsl_sf_ellint_Kcomp_e(std::sqrt(std::max(k2, 0.0)), GSL_PREC_DOUBLE, &K) != GSL_SUCCESS)
    return std::numeric_limits<double>::infinity();
  return 4 * K.val / lambda;
}

FreeRotation free_rotation(const Vec3& moments, const Vec3& omega) {
  if (!(moments[0] > 0 && moments[0] <= moments[1] && moments[1] <= moments[2]))
    throw std::invalid_argument(
        fmt::format("principal moments must be positive and ascending, not ({}, {}, {})", moments[0],
                    moments[1], moments[2]));
  FreeRotation motion;
  motion.moments = moments;
  motion.energy = 0.5 * omega.dot(moments.cwiseProduct(omega));
  motion.momentum = moments.cwiseProduct(omega).norm();
  return motion;
}

}  // namespace kit
