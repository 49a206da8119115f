// ex 4.2: one embedded Runge–Kutta step from a Butcher tableau (embedded_rk.hpp).
#include <cmath>

#include <kit_catch.hpp>

#include <kit/ode/reference_solver.hpp>
#include <kit/problems/adaptive_rk_models.hpp>

#include "cases.hpp"
#include "embedded_rk.hpp"

using kit::Vec4;

TEST_CASE("ex 4.2: one Cash–Karp step matches GSL's rkck, solution and error estimate, to 1e-14",
          "[grade][04-adaptive-rk][ex4.2]") {
  const kit::Arenstorf f;
  auto rng = kit::test::random_engine();
  // A state at least 0.2 from the Earth (−μ, 0) and the Moon (1 − μ, 0): a step of h ≤ 0.05 from
  // nearer could pass through one, where every method's stages are infinite (1 seed in 1500 did).
  const auto far_from_the_bodies = [](const Vec4& y) {
    return std::hypot(y[0] + kit::Arenstorf::mu, y[1]) >= 0.2 &&
           std::hypot(y[0] - 1 + kit::Arenstorf::mu, y[1]) >= 0.2;
  };
  for (int trial = 0; trial < 20; ++trial) {
    Vec4 y;
    do {
      y = Vec4(kit::test::uniform(rng, -1, 1), kit::test::uniform(rng, -1, 1), kit::test::uniform(rng, -1, 1),
               kit::test::uniform(rng, -1, 1));
    } while (!far_from_the_bodies(y));
    const double h = kit::test::uniform(rng, 1e-4, 0.05), t = kit::test::uniform(rng, 0, 10);
    const auto mine = kit::embedded_step(f, kit::cash_karp(), t, y, h, f(t, y));
    const auto gsl = kit::gsl_single_step(f, kit::GslStepper::rkck, t, y, h);
    INFO("trial " << trial << ", h = " << h);
    // Round-off grows with the step's own size: near the Moon one step moves y by more than 1.
    // The error estimate h Σ (b_i − b*_i) k_i sums the same stages: its round-off scales with them
    // too, not with the estimate alone (GCC 14 once missed 1e-14 (1 + |error|) by 7%, |error| 706).
    const double moved = (gsl.y - y).cwiseAbs().maxCoeff();
    CHECK((mine.y - gsl.y).cwiseAbs().maxCoeff() <= 1e-14 * (1 + y.cwiseAbs().maxCoeff() + 4 * moved));
    const double estimate = gsl.error.cwiseAbs().maxCoeff();
    CHECK((mine.error - gsl.error).cwiseAbs().maxCoeff() <= 1e-14 * (1 + estimate + 4 * moved));
    CHECK(mine.evaluations == 5);
  }
}

TEST_CASE("ex 4.2: Dormand–Prince is FSAL: the last stage is f(t + h, y_{n+1}), 6 new evaluations",
          "[grade][04-adaptive-rk][ex4.2]") {
  const kit::Arenstorf f;
  const Vec4 y = kit::Arenstorf::initial_state();
  const auto step = kit::embedded_step(f, kit::dormand_prince(), 0.0, y, 0.01, f(0.0, y));
  CHECK(step.evaluations == 6);
  CHECK((step.last_stage - f(0.01, step.y)).cwiseAbs().maxCoeff() <= 1e-12);
}

TEST_CASE("ex 4.2: the propagated solution has the tableau's order, the error estimate the next one down",
          "[grade][04-adaptive-rk][ex4.2]") {
  // One step on y' = y from y = 1: error of y ∝ h^(p+1), of the estimate ∝ h^(q+1).
  using V = kit::Vec<1>;
  const auto growth = [](double, const V& y) { return V(y[0]); };
  for (const auto* tableau : {&kit::cash_karp(), &kit::dormand_prince(), &kit::bogacki_shampine()}) {
    INFO(tableau->name);
    const auto local = [&](double h) {
      return std::abs(kit::embedded_step(growth, *tableau, 0.0, V(1.0), h, V(1.0)).y[0] - std::exp(h));
    };
    const auto estimate = [&](double h) {
      return std::abs(kit::embedded_step(growth, *tableau, 0.0, V(1.0), h, V(1.0)).error[0]);
    };
    CHECK(std::log2(local(0.2) / local(0.1)) == Approx(tableau->order + 1).margin(0.3));
    CHECK(std::log2(estimate(0.2) / estimate(0.1)) == Approx(tableau->embedded_order + 1).margin(0.3));
  }
}
