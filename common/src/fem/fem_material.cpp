#include <kit/fem/fem_material.hpp>

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace kit {
namespace {

void require_material(double young, double poisson) {
  if (!(young > 0) || !std::isfinite(young))
    throw std::invalid_argument(
        fmt::format("Young's modulus {} Pa: expected a positive finite number", young));
  if (!(poisson > -1 && poisson < 0.5))  // the energy is positive definite only there
    throw std::invalid_argument(fmt::format("Poisson's ratio {}: expected (-1, 0.5)", poisson));
}

}  // namespace

Lame lame_3d(double young, double poisson) {
  require_material(young, poisson);
  return {young * poisson / ((1 + poisson) * (1 - 2 * poisson)), young / (2 * (1 + poisson))};
}

Lame plane_stress_lame(double young, double poisson) {
  require_material(young, poisson);
  return {young * poisson / (1 - poisson * poisson), young / (2 * (1 + poisson))};
}

double cantilever_tip_deflection(double load_per_length, double length, double young, double second_moment) {
  return load_per_length * std::pow(length, 4) / (8 * young * second_moment);
}

double timoshenko_tip_deflection(double load_per_length, double length, double young, double second_moment,
                                 double shear_modulus, double area, double shear_coefficient) {
  return cantilever_tip_deflection(load_per_length, length, young, second_moment) +
         load_per_length * length * length / (2 * shear_coefficient * shear_modulus * area);
}

double rectangle_second_moment(double width, double height) { return width * height * height * height / 12; }

}  // namespace kit
