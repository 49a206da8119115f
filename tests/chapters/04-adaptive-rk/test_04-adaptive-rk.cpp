// Chapter 4 end to end: the tableau checks, Hairer's counts, the peers' counts, the
// work-precision comparison, the step-doubling trap, stiffness, figures and bad input.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <tuple>

#include <kit_catch.hpp>
#include <nlohmann/json.hpp>

#include <kit/base/measure.hpp>

#include "chapter_run.hpp"
#include "process.hpp"
#include "van_der_pol_stiffness.hpp"

using nlohmann::json;

namespace {
const std::string binary = KIT_CHAPTER_BINARY;

const json& default_run() {
  static const json summary = kit::test::run_chapter_json(binary, {}, "ch04");
  return summary;
}

// Evaluations a method needs to reach `error`, from its work-precision points. A method that
// never gets there within the sweep needs more than the most it spent trying.
double evaluations_to_reach(const json& points, double error) {
  std::vector<double> cost, err;
  for (const auto& p : points) cost.push_back(p["evaluations"]), err.push_back(p["error"]);
  const double reached = kit::cost_to_reach(cost, err, error);
  return std::isnan(reached) ? *std::max_element(cost.begin(), cost.end()) : reached;
}

const json& at_tolerance(const json& points, double tolerance) {
  for (const auto& p : points)
    if (std::abs(double(p["tolerance"]) / tolerance - 1) < 1e-9) return p;
  throw std::runtime_error("no point at that tolerance");
}
}  // namespace

TEST_CASE("chapter 4 checks the tableaus: Cash–Karp and DOPRI5 5(4), BS 3(2), the lecture's misprint 2 (1 "
          "autonomous)") {
  std::map<std::string, std::array<int, 3>> expected{
      {"Cash-Karp 5(4)", {5, 4, 5}},
      {"Dormand-Prince 5(4)", {5, 4, 5}},
      {"Bogacki-Shampine 3(2)", {3, 2, 3}},
      {"the lecture's tableau, as printed (-575/13824)", {2, 2, 1}}};
  for (const auto& t : default_run()["tableaus"]) {
    const auto& e = expected.at(std::string(t["name"]));
    CHECK(t["order"] == e[0]);
    CHECK(t["embedded_order"] == e[1]);
    CHECK(t["order_autonomous"] == e[2]);
  }
}

TEST_CASE("chapter 4's DOPRI5 takes Hairer's counts on Arenstorf: 985, 2161, 5047 evaluations") {
  const json& wp = default_run()["work_precision"];
  CHECK(at_tolerance(wp["DOPRI5 (kit)"], 1e-6)["evaluations"] == 985);
  CHECK(at_tolerance(wp["DOPRI5 (kit)"], 1e-8)["evaluations"] == 2161);
  CHECK(at_tolerance(wp["DOPRI5 (kit)"], 1e-10)["evaluations"] == 5047);
  CHECK(at_tolerance(wp["DOPRI5 (kit)"], 1e-6)["rejected"] == 23);
  for (const auto& [tol, steps, rejected] :
       {std::tuple{1e-6, 164L, 23L}, {1e-8, 360L, 21L}, {1e-10, 841L, 0L}}) {
    const json& p = at_tolerance(wp["DOPRI5 (kit)"], tol);  // Hairer's steps count accepted and rejected ones
    CHECK(long(p["accepted"]) + long(p["rejected"]) == steps);
    CHECK(p["rejected"] == rejected);
  }
  const json& d = default_run()["detail"];
  CHECK(d["rhs_evals"] == 985);
  CHECK(d["accepted"] == 141);
  CHECK(d["rejected"] == 23);
  // The peers, run in the same process, spend what they are known to spend.
  CHECK(at_tolerance(wp["GSL rkck"], 1e-8)["evaluations"] == 2383);
  CHECK(at_tolerance(wp["GSL rkf45"], 1e-8)["evaluations"] == 2611);
  CHECK(at_tolerance(wp["GSL rk8pd"], 1e-8)["evaluations"] == 2185);
  CHECK(at_tolerance(wp["Boost.Odeint dopri5"], 1e-8)["evaluations"] == 2491);
  // GSL's accepted and rejected steps are its own (its evolve object's): 6 evaluations per attempt.
  const json& rkck = at_tolerance(wp["GSL rkck"], 1e-8);
  CHECK(rkck["accepted"] == 338);
  CHECK(rkck["rejected"] == 59);
  CHECK(long(rkck["evaluations"]) == 1 + 6 * (long(rkck["accepted"]) + long(rkck["rejected"])));
  // Boost.Odeint reports its accepted steps only: the rejected ones are unknown, not 0.
  CHECK(at_tolerance(wp["Boost.Odeint dopri5"], 1e-8)["accepted"].is_number_integer());
  CHECK(at_tolerance(wp["Boost.Odeint dopri5"], 1e-8)["rejected"].is_null());
}

TEST_CASE("chapter 4's DOPRI5 reaches every error from 1e-3 to 1e-7 with fewer evaluations than GSL rkck, "
          "rkf45 and Boost dopri5") {
  const json& wp = default_run()["work_precision"];
  for (double error : {1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7}) {
    const double kit_cost = evaluations_to_reach(wp["DOPRI5 (kit)"], error);
    REQUIRE(std::isfinite(kit_cost));
    for (const char* peer : {"GSL rkck", "GSL rkf45", "Boost.Odeint dopri5"}) {
      INFO("error " << error << ": kit " << kit_cost << ", " << peer << " "
                    << evaluations_to_reach(wp[peer], error));
      CHECK(kit_cost < evaluations_to_reach(wp[peer], error));
    }
  }
}

TEST_CASE("chapter 4: the lecture's step doubling with E_max/E_min = 2.5 < 4 is reported trapped; guarded, "
          "it finishes") {
  const json& sd = default_run()["step_doubling"];
  CHECK(sd["lecture"]["status"] == "trapped");
  CHECK_THAT(std::string(sd["lecture"]["message"]), ContainsSubstring("retries"));
  CHECK(sd["guarded"]["status"] == "finished");
  CHECK(long(sd["guarded"]["evaluations"]) % 3 == 0);  // three Euler steps per trial
}

TEST_CASE("chapter 4: on stiff Van der Pol (μ = 100) DOPRI5 finishes, with the step held near the stability "
          "limit") {
  const json& v = default_run()["van_der_pol"];
  CHECK(v["status"] == "finished");
  CHECK(long(v["accepted"]) > 10'000);
  CHECK(double(v["median_step"]) < 0.05);  // against ~1 where accuracy alone would allow it
  CHECK(double(v["median_h_lambda"]) ==
        Approx(3.31).epsilon(0.15));  // on DOPRI5's real-axis stability boundary
  // Independently of that median: with h·μ(x² − 1) = 3.31 on the four slow branches of two periods,
  // the step count is 4·(μ²/3.31)·∫₁² (x² − 1)²/x dx = 4·(ln 2 + 3/4)·μ²/3.31 = 17 440 at μ = 100.
  CHECK(double(v["accepted"]) == Approx(4 * (std::log(2.0) + 0.75) * 100 * 100 / 3.31).epsilon(0.05));
}

TEST_CASE("chapter 4 never refuses a large --mu: past the step budget, Van der Pol's horizon shrinks and it "
          "says so") {
  kit::test::TempDir out("ch04-stiff");
  const auto result =
      kit::test::run_process(binary, {"--quiet", "--mu", "1e4", "--out", out.path().string()});
  REQUIRE(result.exit_code == 0);
  const auto run =
      kit::test::run_process(binary, {"--json", "--no-plot", "--mu", "1e4", "--out", out.path().string()});
  REQUIRE(run.exit_code == 0);
  const json v = json::parse(run.out)["van_der_pol"];
  CHECK(v["adapted"] == true);  // two periods would take ~1.7e8 steps
  CHECK(double(v["predicted_steps"]) > 1e8);
  CHECK(long(v["accepted"]) + long(v["rejected"]) == long(v["budget"]));
  CHECK(double(v["horizon"]) < double(v["two_periods"]) / 100);
  CHECK(double(v["horizon"]) > 0);
  CHECK(double(v["median_h_lambda"]) ==
        Approx(3.31).epsilon(0.15));  // still stability-bound on what it covered
  // The figure draws at most 20 000 of the 2e6 accepted steps.
  std::ifstream data(out.path() / "van-der-pol.dat");
  CHECK(std::count(std::istreambuf_iterator<char>(data), std::istreambuf_iterator<char>(), '\n') < 50'000);
}

TEST_CASE(
    "chapter 4: at μ = 10 the step is below the stability limit, and the chapter says accuracy decides") {
  kit::test::TempDir out("ch04-mild");
  const auto result =
      kit::test::run_process(binary, {"--json", "--no-plot", "--mu", "10", "--out", out.path().string()});
  REQUIRE(result.exit_code == 0);
  const json v = json::parse(result.out)["van_der_pol"];
  CHECK(double(v["median_h_lambda"]) < 2.5);
  CHECK(v["stability_bound"] == false);
}

TEST_CASE("chapter 4: GSL's 8th-order rk8pd needs fewer evaluations than the 5th-order DOPRI5 here, as its "
          "order predicts") {
  const json& wp = default_run()["work_precision"];
  for (double error : {1e-3, 1e-5, 1e-7})
    CHECK(evaluations_to_reach(wp["GSL rk8pd"], error) < evaluations_to_reach(wp["DOPRI5 (kit)"], error));
}

TEST_CASE("chapter 4 on Kepler: errors against the exact solution shrink with the tolerance") {
  kit::test::TempDir out("ch04-kepler");
  const auto result = kit::test::run_process(binary, {"--json", "--no-plot", "--problem", "kepler",
                                                      "--eccentricity", "0.5", "--out", out.path().string()});
  REQUIRE(result.exit_code == 0);
  const json wp = json::parse(result.out)["work_precision"]["DOPRI5 (kit)"];
  CHECK(double(at_tolerance(wp, 1e-10)["error"]) < 1e-7);
  CHECK(double(at_tolerance(wp, 1e-10)["error"]) < double(at_tolerance(wp, 1e-6)["error"]));
}

TEST_CASE("chapter 4 writes its five figures, with no gnuplot warning") {
  kit::test::TempDir out("ch04-figures");
  const auto result = kit::test::run_process(binary, {"--quiet", "--out", out.path().string()});
  REQUIRE(result.exit_code == 0);
  CHECK(result.err.empty());
  for (const char* name : {"orbit", "step-sizes", "work-precision", "work-precision-timing", "van-der-pol"})
    CHECK(std::filesystem::file_size(out.path() / (std::string(name) + ".png")) > 1000);
}

TEST_CASE("chapter 4 answers bad input with exit 2, a message naming the flag, and no file") {
  kit::test::expect_usage_errors(binary, {{{"--rtol", "0"}, "--rtol"},
                                          {{"--problem", "lorenz"}, "--problem"},
                                          {{"--method", "DOPRI5"}, "--method"},
                                          {{"--emin", "1e-3", "--emax", "1e-4"}, "--emin"},
                                          {{"--mu", "-1"}, "--mu"},
                                          {{"--eccentricity", "1"}, "--eccentricity"},
                                          {{"--bogus"}, "--bogus"}});
}

TEST_CASE("Van der Pol's estimate: the predicted steps, or the budget when fewer") {
  // A stand-in DOPRI5 for the calibration (the estimate's steps do not depend on it): explicit
  // Euler steps of 1e-3, as many as it is asked for.
  const kit::Dopri5Runner euler = [](const kit::VanDerPol& f, const kit::Vec2& y0, double, long max_steps) {
    kit::AdaptiveRun<kit::Vec2> run;
    kit::Vec2 y = y0;
    for (long k = 0; k < max_steps; ++k) y += 1e-3 * f(1e-3 * double(k), y), run.step_sizes.push_back(1e-3);
    run.accepted.push(1e-3 * double(max_steps), y);
    return run;
  };
  CHECK(kit::van_der_pol_estimate(100, euler).steps == Approx(4 * (std::log(2.0) + 0.75) * 1e4 / 3.31));
  const kit::RunEstimate big = kit::van_der_pol_estimate(1e4, euler, 2'000'000);
  CHECK(big.steps == 2'000'000);
  CHECK(big.bytes == 48 * 2e6);
  CHECK(big.seconds_per_step > 0);
}
