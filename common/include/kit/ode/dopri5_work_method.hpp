#pragma once
// The production DOPRI5 (dopri5.hpp) as a method of the work-precision harness
// (work_precision.hpp). Production code: a student edition without it leaves this file out.
#include <utility>
#include <vector>

#include <kit/app/look.hpp>
#include <kit/ode/dopri5.hpp>
#include <kit/ode/work_precision.hpp>

namespace kit {

/// The kit's DOPRI5: accepted and rejected steps; unfinished when it stops before t1.
template <int N, class Rhs>
WorkMethod<N> dopri5_method(Rhs f, double t0, const Vec<N>& y0, double t1, double h0,
                            std::vector<double> tolerances) {
  return {"DOPRI5 (kit)", look::dopri5 + " pt 7 lw 2", std::move(tolerances), [=](double tol) {
            Dopri5Options options;
            options.rtol = options.atol = tol;
            options.h0 = h0;
            const auto r = dopri5(f, t0, y0, t1, options);
            return WorkRun<N>{r.y, r.stats.rhs_evals, r.stats.steps, r.stats.rejected,
                              r.status == RunStatus::finished};
          }};
}

}  // namespace kit
