// Chapter 9's material: Lamé's parameters in 3-D and in plane stress, and the cantilever's closed
// form the finite elements converge to.
#include <kit_catch.hpp>

#include <kit/fem/fem_material.hpp>

TEST_CASE("fem material: plane stress's λ* is 2λμ/(λ + 2μ) of the 3-D Lamé parameters; the cantilever's "
          "closed form",
          "[fem][material]") {
  for (double nu : {-0.5, 0.0, 0.25, 0.3, 0.49}) {
    const kit::Lame three = kit::lame_3d(2e5, nu), plane = kit::plane_stress_lame(2e5, nu);
    INFO("ν = " << nu);
    CHECK(three.mu == Approx(2e5 / (2 * (1 + nu))));
    CHECK(plane.mu == three.mu);
    // σ_zz = λ tr ε + 2μ ε_zz = 0 eliminates ε_zz: λ* = λ − λ²/(λ + 2μ) = 2λμ/(λ + 2μ).
    CHECK(plane.lambda == Approx(2 * three.lambda * three.mu / (three.lambda + 2 * three.mu)).margin(1e-9));
    // Young's modulus back from Lamé: E = μ (3λ + 2μ)/(λ + μ).
    CHECK(three.mu * (3 * three.lambda + 2 * three.mu) / (three.lambda + three.mu) == Approx(2e5));
  }
  CHECK_THROWS_AS(kit::lame_3d(1, 0.5), std::invalid_argument);
  CHECK_THROWS_AS(kit::plane_stress_lame(0, 0.3), std::invalid_argument);
  // A steel ruler, 30 × 3 × 0.1 cm, under its own weight (7850 kg/m³): 4.68 mm at its tip.
  const double second_moment = kit::rectangle_second_moment(0.03, 0.001);
  CHECK(second_moment == Approx(2.5e-12));
  const double q = 7850 * 9.81 * 0.03 * 0.001;  // [N/m]
  CHECK(kit::cantilever_tip_deflection(q, 0.3, 2e11, second_moment) ==
        Approx(q * 0.0081 / (8 * 2e11 * 2.5e-12)));
  CHECK(kit::cantilever_tip_deflection(q, 0.3, 2e11, second_moment) == Approx(4.678e-3).epsilon(1e-3));
}

TEST_CASE("fem material: Timoshenko adds q L² / (2 κ G A) to Euler–Bernoulli", "[fem][material]") {
  // A 1 m × 0.1 m beam, 1 cm thick, E = 1 GPa, ν = 0.3: the shear share is (E / (3 κ G)) (h/L)²
  // of the bending's, 2.6 / 2.5 × 1% = 1.04%.
  const double q = 1000 * 9.81 * 0.1 * 0.01, second_moment = kit::rectangle_second_moment(0.01, 0.1);
  const double bending = kit::cantilever_tip_deflection(q, 1, 1e9, second_moment);
  const double shear_modulus = 1e9 / 2.6;
  const double both = kit::timoshenko_tip_deflection(q, 1, 1e9, second_moment, shear_modulus, 0.001);
  CHECK(both - bending == Approx(q / (2 * 5.0 / 6.0 * shear_modulus * 0.001)).epsilon(1e-14));
  CHECK(both / bending - 1 == Approx(0.0104).epsilon(1e-12));
}
