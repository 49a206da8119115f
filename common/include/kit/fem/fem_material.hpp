#pragma once
// Chapter 9's material and its closed forms (lecture, "Mécanique des milieux continus"; errata 16:
// the lecture's σ = E ε is the 1-D Hooke law, and 3-D linear elasticity uses Lamé's λ and μ).
namespace kit {

/// Lamé's parameters [Pa]: σ = λ tr(ε) I + 2μ ε (linear), S = λ tr(E) I + 2μ E (St Venant–Kirchhoff).
struct Lame {
  double lambda = 0;
  double mu = 0;  ///< the shear modulus G
};

/// 3-D Lamé parameters from Young's modulus E [Pa] > 0 and Poisson's ratio ν in (−1, 0.5):
/// μ = E / (2 (1 + ν)), λ = E ν / ((1 + ν)(1 − 2ν)). Throws std::invalid_argument outside those ranges.
Lame lame_3d(double young, double poisson);
/// Plane stress (a thin plate, σ_zz = 0): the same μ, and λ* = E ν / (1 − ν²) = 2λμ / (λ + 2μ) in
/// terms of the 3-D ones. Throws as lame_3d.
Lame plane_stress_lame(double young, double poisson);

/// Euler–Bernoulli: the tip deflection of a cantilever of length L [m] under a uniform load q
/// [N/m], q L⁴ / (8 E I), with E [Pa] and the section's second moment I [m⁴].
double cantilever_tip_deflection(double load_per_length, double length, double young, double second_moment);
/// Timoshenko's, which adds the shear's share: q L⁴ / (8 E I) + q L² / (2 κ G A), with the
/// shear modulus G [Pa], the section's area A [m²] and its shear coefficient κ (5/6 for a
/// rectangle). A beam 10 times longer than high sags about 1% more than Euler–Bernoulli says.
double timoshenko_tip_deflection(double load_per_length, double length, double young, double second_moment,
                                 double shear_modulus, double area, double shear_coefficient = 5.0 / 6.0);
/// The second moment of a rectangular section of width b and height h [m] about its neutral
/// axis, b h³ / 12 [m⁴].
double rectangle_second_moment(double width, double height);

}  // namespace kit
