// Chapter 2 end to end: the binary's --json numbers against theory (ERRATA items 4–7), its
// figures, divergence as a reported result, and bad input.
#include <cmath>

#include <kit_catch.hpp>
#include <nlohmann/json.hpp>

#include "chapter_run.hpp"
#include "process.hpp"

using nlohmann::json;

namespace {
const std::string binary = KIT_CHAPTER_BINARY;

json run_chapter(const std::vector<std::string>& args, int expected_exit = 0) {
  return kit::test::run_chapter_json(binary, args, "ch02", expected_exit);
}

// The default run, shared by the tests that only read it.
const json& default_run() {
  static const json summary = run_chapter({});
  return summary;
}
}  // namespace

TEST_CASE("chapter 2: each critical step is within 1% of theory, for three (m, K, μ) sets") {
  // (m, K, μ): the explicit row uses μ when underdamped; symplectic and RK4 use the undamped spring.
  for (auto [m, k, mu] : {std::tuple{1.0, 100.0, 2.0}, {0.5, 2000.0, 6.0}, {3.0, 12.0, 1.5}}) {
    const auto s = run_chapter(
        {"--mass", std::to_string(m), "--stiffness", std::to_string(k), "--damping", std::to_string(mu)});
    const double omega = std::sqrt(k / m);
    INFO("m = " << m << ", K = " << k << ", mu = " << mu);
    const json& c = s["critical"];
    CHECK(double(c["explicit_euler"]["closed_form"]) == Approx(mu / k).epsilon(1e-12));
    CHECK(double(c["symplectic_euler"]["closed_form"]) == Approx(2 / omega).epsilon(1e-12));
    CHECK(double(c["rk4"]["closed_form"]) == Approx(2 * std::sqrt(2.0) / omega).epsilon(1e-12));
    CHECK(double(c["explicit_euler"]["measured"]) == Approx(mu / k).epsilon(0.01));
    CHECK(double(c["symplectic_euler"]["measured"]) == Approx(2 / omega).epsilon(0.01));
    CHECK(double(c["rk4"]["measured"]) == Approx(2 * std::sqrt(2.0) / omega).epsilon(0.01));
  }
}

TEST_CASE("chapter 2: undamped explicit Euler grows by exactly sqrt(1 + ω²Δt²) per step, implicit shrinks by "
          "its inverse") {
  for (double dt : {0.001, 0.02, 0.05}) {
    const auto s = run_chapter({"--dt", std::to_string(dt), "--t-end", "1"});
    const double h = 10.0 * dt;  // ω = 10 rad/s by default
    INFO("dt = " << dt);
    CHECK(double(s["runs"]["explicit_euler"]["growth_per_step"]) ==
          Approx(std::sqrt(1 + h * h)).epsilon(1e-12));
    CHECK(double(s["runs"]["implicit_euler"]["growth_per_step"]) ==
          Approx(1 / std::sqrt(1 + h * h)).epsilon(1e-12));
    CHECK(double(s["runs"]["explicit_euler"]["spectral_radius"]) ==
          Approx(std::sqrt(1 + h * h)).epsilon(1e-14));
  }
}

TEST_CASE("chapter 2: symplectic Euler keeps the energy bounded, explicit grows, implicit decays") {
  const auto s = run_chapter({"--t-end", "20"});
  CHECK(s["runs"]["explicit_euler"]["diverged"] ==
        true);  // grows by 1.0198 per step: past 1e8 within 1000 steps
  CHECK(double(s["runs"]["implicit_euler"]["energy_ratio"]) < 1e-10);
  // Over the whole run, not at one instant: |E/E0 − 1| ≤ ωΔt/(2 − ωΔt) (from the invariant
  // x² + v² − Δt·x·v of symplectic Euler, starting at rest), ωΔt = 0.2 here.
  CHECK(double(s["runs"]["symplectic_euler"]["max_energy_drift"]) <= 0.2 / (2 - 0.2) * (1 + 1e-9));
  CHECK(double(s["runs"]["symplectic_euler"]["max_energy_drift"]) > 0.05);  // and it does oscillate
  CHECK(double(s["reference_max_gap"]) < 1e-10);                            // GSL agrees with the closed form
}

TEST_CASE("chapter 2: implicit Euler's damping per step is 1/sqrt(1 + ω²Δt²), up to ω·Δt = 100") {
  const auto& s = default_run();
  REQUIRE(s["implicit_damping"].size() == 7);
  for (const auto& row : s["implicit_damping"]) {
    const double h = row["omega_dt"];
    CHECK(double(row["per_step"]) == Approx(1 / std::sqrt(1 + h * h)).epsilon(1e-9));
  }
}

TEST_CASE(
    "chapter 2: a stiff spring (ω = 1e6 rad/s) makes the explicit schemes diverge, reported, not a crash") {
  const json& stiff = default_run()["extremes"]["stiff, ω = 1e6 rad/s"];
  CHECK(stiff["explicit_euler"] == 1);
  CHECK(stiff["rk4"] == 1);
  CHECK(stiff["implicit_euler"].is_null());  // null: finished without diverging
  CHECK(double(default_run()["extremes_amplitude"]["stiff, ω = 1e6 rad/s"]["implicit_euler"]) <
        1e-100);  // killed
  CHECK(default_run()["extremes_amplitude"]["stiff, ω = 1e6 rad/s"]["rk4"]
            .is_null());  // no amplitude: diverged
  // A diverging main run is listed, and --fail-on-divergence turns it into exit code 3.
  const auto diverging = run_chapter({"--stiffness", "1e8", "--dt", "0.01"});
  REQUIRE(diverging.contains("divergences"));
  CHECK(diverging["runs"]["explicit_euler"]["energy_ratio"]
            .is_null());  // no fake E(T) for a run that never got there
  CHECK_THAT(std::string(diverging["divergences"][0]["what"]), ContainsSubstring("diverged at step"));
  run_chapter({"--stiffness", "1e8", "--dt", "0.01", "--fail-on-divergence"}, 3);
}

TEST_CASE("chapter 2 on an extreme spring inside the flag ranges still finishes: the GSL cross-check is "
          "reported unavailable") {
  const auto s = run_chapter({"--mass", "1e-6", "--stiffness", "1e15", "--dt", "1", "--t-end", "1"});
  CHECK(s["reference_max_gap"].is_null());
  CHECK_THAT(std::string(s["reference_note"]), ContainsSubstring("GSL"));  // and says why
  CHECK(s["runs"]["implicit_euler"]["diverged"] == false);
}

TEST_CASE("chapter 2 writes its six figures, with no gnuplot warning") {
  kit::test::TempDir out("ch02-figures");
  const auto result = kit::test::run_process(binary, {"--quiet", "--out", out.path().string()});
  REQUIRE(result.exit_code == 0);
  CHECK(result.err.empty());
  for (const char* name :
       {"positions", "phase", "energy", "amplification", "stability-regions", "stability-map"})
    for (const char* ext : {".dat", ".gp", ".pdf", ".png"})
      CHECK(std::filesystem::file_size(out.path() / (std::string(name) + ext)) > 100);
  CHECK(kit::test::files_under(out.path()).size() == 24);
}

TEST_CASE("chapter 2 answers bad input with exit 2, a message naming the flag, and no file") {
  kit::test::expect_usage_errors(binary, {{{"--mass", "-1"}, "--mass"},
                                          {{"--dt", "0"}, "--dt"},
                                          {{"--stiffness", "nan"}, "--stiffness"},
                                          {{"--damping", "-0.5"}, "--damping"},
                                          {{"--bogus"}, "--bogus"},
                                          {{"--x0", "1", "--rest-length", "1"}, "--x0"}});
}

TEST_CASE("chapter 2 refuses a valid run too large to record with exit 2, its memory estimate, and no file") {
  // Every flag is in its range, but 1e5 s in steps of 1e-9 s is 1e14 steps to record.
  kit::test::TempDir out("ch02-huge");
  const auto target = out.path() / "figures";
  const auto result =
      kit::test::run_process(binary, {"--t-end", "1e5", "--dt", "1e-9", "--out", target.string()});
  INFO(result.err);
  CHECK(result.exit_code == 2);
  CHECK_THAT(result.err, ContainsSubstring("--t-end 100000 s with --dt 1e-09 s is 1e+14 steps") &&
                             ContainsSubstring("recording them would take 16 PB") &&
                             ContainsSubstring("at most 1000000 steps, 160 MB, are recorded"));
  CHECK(result.out.empty());
  CHECK_FALSE(std::filesystem::exists(target));
}
