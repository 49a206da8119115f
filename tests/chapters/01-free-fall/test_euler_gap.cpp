// ERRATA item 1 checked on runs (euler_gap.hpp): both Euler gaps equal k/2·Δt²·|g|, each on its side.
#include <kit_catch.hpp>

#include "euler_gap.hpp"

namespace {
// Gaps x_k − x̃(kΔt) of Euler loops run here: explicit (x with the old v) and implicit (v first).
std::pair<std::vector<double>, std::vector<double>> loop_gaps(const kit::FreeFall& fall, double dt, long n) {
  std::vector<double> e, i;
  double xe = fall.x0, ve = fall.v0, xi = fall.x0, vi = fall.v0;
  for (long k = 0; k <= n; ++k) {
    e.push_back(xe - fall.position(double(k) * dt)), i.push_back(xi - fall.position(double(k) * dt));
    xe += dt * ve, ve += dt * fall.g;
    vi += dt * fall.g, xi += dt * vi;
  }
  return {e, i};
}
}  // namespace

TEST_CASE("real Euler runs match the prediction at every step, for g < 0 and g > 0") {
  for (double g : {-9.81, 4.0}) {
    kit::FreeFall fall;
    fall.x0 = 7, fall.v0 = 3, fall.g = g;
    const auto [e, i] = loop_gaps(fall, 0.05, 30);
    const auto check = kit::check_euler_gaps(fall, 0.05, 1.5, e, i);
    INFO("g = " << g);
    REQUIRE(check.match.size() == 31);
    for (bool m : check.match) CHECK(m);
    CHECK(check.predicted[30] == Approx(15 * 0.0025 * std::abs(g)).epsilon(1e-14));  // k/2·Δt²·|g| by hand
    CHECK(check.mismatch < 1e-12);
  }
}

TEST_CASE("a gap on the wrong side, or off by the lecture's missing |g|, does not match") {
  kit::FreeFall fall;
  const auto [e, i] = loop_gaps(fall, 0.1, 10);
  const auto swapped = kit::check_euler_gaps(fall, 0.1, 1.0, i, e);  // explicit below, implicit above
  CHECK_FALSE(swapped.match[10]);
  CHECK(swapped.match[0]);      // k = 0: no gap, no side
  std::vector<double> lecture;  // k/2·Δt² without |g|
  for (long k = 0; k <= 10; ++k) lecture.push_back(0.5 * double(k) * 0.01);
  std::vector<double> minus(lecture.size());
  for (std::size_t k = 0; k < lecture.size(); ++k) minus[k] = -lecture[k];
  const auto wrong = kit::check_euler_gaps(fall, 0.1, 1.0, lecture, minus);
  CHECK_FALSE(wrong.match[10]);
  CHECK(wrong.mismatch == Approx(0.5 * 10 * 0.01 * (9.81 - 1)).epsilon(1e-12));
}

TEST_CASE("a scheme not written yet (an empty run) leaves the other checked alone") {
  kit::FreeFall fall;
  const auto [e, i] = loop_gaps(fall, 0.1, 10);
  const auto explicit_only = kit::check_euler_gaps(fall, 0.1, 1.0, e, {});
  REQUIRE(explicit_only.match.size() == 11);
  for (bool m : explicit_only.match) CHECK(m);
  const auto implicit_only = kit::check_euler_gaps(fall, 0.1, 1.0, {}, i);
  REQUIRE(implicit_only.match.size() == 11);
  for (bool m : implicit_only.match) CHECK(m);
  CHECK_FALSE(kit::check_euler_gaps(fall, 0.1, 1.0, i, {}).match[10]);  // alone, still on its side
  const auto neither = kit::check_euler_gaps(fall, 0.1, 1.0, {}, {});
  CHECK(neither.match.empty());
  REQUIRE(neither.predicted.size() == 11);  // the prediction is there before any scheme runs
  CHECK(neither.predicted[10] == Approx(5 * 0.01 * 9.81).epsilon(1e-14));
  CHECK_THROWS_AS(kit::check_euler_gaps(fall, 0.1, 1.0, e, std::vector<double>(3)), std::invalid_argument);
}
