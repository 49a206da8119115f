// Chapter 3 end to end: midpoint RK2 exact on free fall, every scheme's fitted order, symplectic
// Euler's bounded energy, the evaluation counts of the cost table, and bad input.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <kit_catch.hpp>
#include <nlohmann/json.hpp>

#include "chapter_run.hpp"
#include "process.hpp"

using nlohmann::json;

namespace {
const std::string binary = KIT_CHAPTER_BINARY;

json run_chapter(const std::vector<std::string>& args) {
  return kit::test::run_chapter_json(binary, args, "ch03");
}

const json& default_run() {
  static const json summary = run_chapter({});
  return summary;
}
}  // namespace

TEST_CASE("chapter 3: midpoint RK2 reproduces free fall to 1e-12 relative after 1e4 steps; Euler does not") {
  const json& f = default_run()["free_fall"];
  CHECK(f["steps"] == 10'000);
  CHECK(double(f["midpoint_relative_error"]) <= 1e-12);
  CHECK(double(f["euler_relative_error"]) > 1e-6);
}

TEST_CASE("chapter 3: fitted orders are within 0.1 of 1, 1, 1, 2 and 4, on two springs") {
  const json damped = run_chapter({"--damping", "3", "--mass", "2", "--stiffness", "50"});
  for (const json* s : {&default_run(), &damped}) {
    for (const auto& [scheme, expected] : std::map<std::string, double>{{"explicit_euler", 1},
                                                                        {"implicit_euler", 1},
                                                                        {"symplectic_euler", 1},
                                                                        {"midpoint", 2},
                                                                        {"rk4", 4}}) {
      INFO(scheme);
      CHECK(double((*s)["orders"][scheme]["expected"]) == expected);
      CHECK(double((*s)["orders"][scheme]["fitted"]) == Approx(expected).margin(0.1));
      CHECK(int((*s)["orders"][scheme]["points"]) >= 3);
    }
  }
}

TEST_CASE("chapter 3: over 1000 periods symplectic Euler's energy error stays below ωΔt/(2 − ωΔt), explicit "
          "Euler's explodes") {
  const json& e = default_run()["energy"];
  // From the invariant x² + v² − Δt·x·v of symplectic Euler (ω = 1 units), starting at rest.
  CHECK(double(e["symplectic_euler"]["max_drift"]) <= 0.1 / (2 - 0.1) * (1 + 1e-9));
  CHECK(double(e["explicit_euler"]["max_drift"]) > 1e100);
  CHECK(double(e["implicit_euler"]["final_ratio"]) < 1e-10);
}

TEST_CASE("chapter 3: the cost table's counts follow the orders: RK4 needs the fewest evaluations") {
  const json& n = default_run()["evaluations_needed"];
  for (const char* tolerance : {"1e-03", "1e-06", "1e-09"}) {
    INFO(tolerance);
    REQUIRE(n["rk4"][tolerance]["reachable"] == true);
    CHECK(n["rk4"][tolerance]["extrapolated"] == false);
    for (const char* other : {"explicit_euler", "symplectic_euler", "midpoint"})
      CHECK(double(n["rk4"][tolerance]["evaluations"]) < double(n[other][tolerance]["evaluations"]));
  }
  // First order cannot reach 1e-9 m before round-off does (chapter 1): reported, not faked.
  CHECK(n["explicit_euler"]["1e-09"]["reachable"] == false);
  // Measured counts are whole numbers of steps times evaluations per step (2 for midpoint).
  CHECK(long(n["midpoint"]["1e-03"]["evaluations"]) % 2 == 0);
}

TEST_CASE("chapter 3 never refuses a valid --t-end or --stiffness for its sweep: it shortens T and says so") {
  // Both were refused before (ω·T > 5000). ω·T = 1e5 (6.3e4 for K = 1e9 N/m) would need 10·(ω·T)² = 1e11
  // steps for a decade of ω·Δt below 1/(ω·T): T becomes sqrt(1e6/10)/ω, the longest 1e6 steps allow.
  for (const auto& [args, t] : std::map<std::vector<std::string>, double>{
           {{"--t-end", "1e4", "--periods", "10"}, std::sqrt(1e5) / 10},
           {{"--stiffness", "1e9", "--periods", "10"}, std::sqrt(1e5 / 1e9)}}) {
    INFO(args[0]);
    const json s = run_chapter(args);
    CHECK(s["spring"]["adapted"] == true);
    CHECK(double(s["spring"]["omega_t_max"]) ==
          Approx(std::sqrt(1e5)).epsilon(1e-12));  // a decade below 1/(ω·T) in 1e6 steps
    CHECK(double(s["spring"]["t"]) == Approx(t).epsilon(1e-12));
    for (const auto& [scheme, order] : std::map<std::string, double>{{"explicit_euler", 1},
                                                                     {"implicit_euler", 1},
                                                                     {"symplectic_euler", 1},
                                                                     {"midpoint", 2},
                                                                     {"rk4", 4}})
      CHECK(double(s["orders"][scheme]["fitted"]) == Approx(order).margin(0.1));  // still the orders
  }
  CHECK(default_run()["spring"]["adapted"] == false);
  CHECK(double(default_run()["spring"]["t"]) == 2.0);
}

TEST_CASE("chapter 3 on a critically damped spring, whose motion dies below round-off: no fit is null, not a "
          "crash") {
  const json s = run_chapter({"--damping", "20", "--periods", "10"});  // μ² = 4mK
  CHECK(double(s["orders"]["explicit_euler"]["fitted"]) == Approx(1).margin(0.1));
  CHECK(long(s["orders"]["rk4"]["points"]) < 2);
  CHECK(s["orders"]["rk4"]["fitted"].is_null());  // NaN in the JSON: nothing to fit
  CHECK(s["evaluations_needed"]["rk4"]["1e-09"]["extrapolated"] == false);
}

TEST_CASE("chapter 3 writes its three figures, with no gnuplot warning") {
  kit::test::TempDir out("ch03-figures");
  const auto result = kit::test::run_process(binary, {"--quiet", "--out", out.path().string()});
  REQUIRE(result.exit_code == 0);
  CHECK(result.err.empty());
  CHECK(kit::test::files_under(out.path()).size() == 12);
}

TEST_CASE("chapter 3 answers bad input with exit 2, a message naming the flag, and no file") {
  kit::test::expect_usage_errors(binary, {{{"--mass", "-1"}, "--mass"},
                                          {{"--t-end", "0"}, "--t-end"},
                                          {{"--stiffness", "2e9"}, "--stiffness"},
                                          {{"--t-end", "2e4"}, "--t-end"},
                                          {{"--stiffness", "nan"}, "--stiffness"},
                                          {{"--periods", "0"}, "--periods"},
                                          {{"--free-fall-steps", "1.5"}, "--free-fall-steps"},
                                          {{"--bogus"}, "--bogus"}});
}
