#pragma once
// Chapter 4's report, its words apart from main.cpp's sections: the tableaus' columns and the
// sentences of the Van der Pol run.
#include <string>
#include <vector>

#include <kit/app/report.hpp>

#include "van_der_pol_stiffness.hpp"

namespace kit {

/// Section 1's table: each tableau's size, row-sum defect and the orders its weights satisfy.
inline std::vector<Column> tableau_columns() {
  return {{"tableau", "name"},
          {"stages", "stages"},
          {"FSAL", "fsal"},
          {"max |c - row sum|", "row_sum_defect", "{:.1e}"},
          {"order of b", "order"},
          {"order of b̂", "embedded_order"},
          {"autonomous: b", "order_autonomous"},
          {"autonomous: b̂", "embedded_order_autonomous"}};
}

/// Section 5's sentences: how far DOPRI5 got on Van der Pol, its steps, and whether stability
/// rather than accuracy set them.
inline void say_van_der_pol(Report& report, const StiffnessRun& s) {
  const std::vector<Field> fields = report_fields(s);
  report.say(
      "van_der_pol",
      s.adapted
          ? "\nVan der Pol, mu = {mu}: two periods (t = {two_periods:.4g}) would take about "
            "{predicted_steps:.2g} steps; DOPRI5's\nbudget of {budget} ran out at t = {horizon:.4g}, so what "
            "follows is over [0, {horizon:.4g}].\n"
          : "\nVan der Pol, mu = {mu}, over {horizon:.4g} (two periods): ",
      fields);
  report.say("van_der_pol",
             "DOPRI5 took {accepted} steps and rejected {rejected}; median step "
             "{median_step:.3g}.\nOn the slow branches the median of h·|λ_stiff| = h·mu·(x² - 1) is "
             "{median_h_lambda:.3g}, against DOPRI5's stability boundary\non the negative real axis, "
             "{boundary}: {verdict}.\n",
             fields);
}

}  // namespace kit
