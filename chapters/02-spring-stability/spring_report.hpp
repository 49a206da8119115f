#pragma once
// Chapter 2's report, its words apart from main.cpp's sections: the spring's sentence and the
// columns of each table (runs, critical steps, implicit Euler's damping, the extremes).
#include <cmath>
#include <string>
#include <vector>

#include <kit/app/report.hpp>
#include <kit/problems/spring.hpp>

#include "spring_stability.hpp"

namespace kit {

/// Section 1's sentences: the spring, the start and the step, then ω, ζ, the period, ω·Δt and
/// the eigenvalues of A [1/s].
inline void say_spring_system(Report& report, const Spring& spring, const Vec2& u0, double dt, long steps) {
  const double w = spring.omega(), zeta = spring.damping_ratio();
  const auto [l1, l2] = spring.eigenvalues();  // {0} below: fmt cannot name the key "rest-length"
  report.say("parameters",
             "Spring: m = {mass} kg, K = {stiffness} N/m, mu = {damping} N·s/m, L0 = {0} m; "
             "u0 = ({x0} m, {v0} m/s); dt = {dt} s\n",
             {{"rest-length", spring.rest_length},
              {"mass", spring.mass},
              {"stiffness", spring.stiffness},
              {"damping", spring.damping},
              {"x0", u0[0]},
              {"v0", u0[1]},
              {"dt", dt}});
  report.say("",
             "omega = {omega:.6g} rad/s, zeta = {zeta:.4g} ({regime}), period 2π/ω = {period:.4g} s, so "
             "omega·dt = {omega_dt:.4g}\neigenvalues of A: {lambda1_re:.4g}{lambda1_im:+.4g}i and "
             "{lambda2_re:.4g}{lambda2_im:+.4g}i [1/s]\n\n",
             {{"omega", w},
              {"zeta", zeta},
              {"period", 2 * M_PI / w},
              {"regime", damping_regime(zeta)},
              {"omega_dt", w * dt},
              {"steps", steps},
              {"lambda1_re", l1.real()},
              {"lambda1_im", l1.imag()},
              {"lambda2_re", l2.real()},
              {"lambda2_im", l2.imag()}});
}

/// Section 2's table: each scheme at Δt; `factor` formats growth and spectral radius.
inline std::vector<Column> run_columns(const std::string& factor) {
  return {{"scheme", ""},
          {"x(T) [m]", "x_end", "{:.6f}"},
          {"|x(T) - exact|", "error_end", "{:.2e}"},
          {"E(T)/E(0)", "energy_ratio", "{:.3e}"},
          {"growth/step", "growth_per_step", factor},
          {"spectral radius", "spectral_radius", factor},
          {"status", "status"},
          {"", "max_energy_drift"},
          {"", "steps"},
          {"", "diverged"}};
}

/// Section 3's table: each critical step measured, from R(z) and in closed form.
inline std::vector<Column> critical_columns() {
  return {{"scheme", ""},
          {"μ [N·s/m]", "damping", "{:.4g}"},
          {"ζ", "zeta", "{:.3g}"},
          {"measured Δt [s]", "measured", "{:.5e}"},
          {"from R(z) [s]", "analytic", "{:.5e}"},
          {"formula", ""},
          {"closed form [s]", "closed_form", "{:.5e}"},
          {"measured vs closed form", "relative_difference", "{:+.2e}"}};
}

/// Section 4's table: the amplitude implicit Euler keeps per step and per period, and predicted.
inline std::vector<Column> implicit_damping_columns() {
  return {{"ω·Δt", "omega_dt", "{:.2f}"},
          {"amplitude kept per step", "per_step", "{:.7e}"},
          {"1/sqrt(1+ω²Δt²)", "predicted_per_step", "{:.7e}"},
          {"per period of the motion", "per_period", "{:.3e}"},
          {"predicted", "predicted_per_period", "{:.3e}"}};
}

/// Section 5's first table, before a column per scheme: the spring, ζ and ω·Δt.
inline std::vector<Column> extremes_columns() {
  return {{"spring", ""}, {"ζ", "zeta", "{:.1f}"}, {"ω·Δt", "omega_dt", "{:.2e}"}};
}

}  // namespace kit
