// The report layer: a printed number and its JSON twin come from one call.
#include <sstream>

#include <catch2/catch.hpp>

#include <kit/report.hpp>

TEST_CASE("say prints each field with its format and stores the same value under its section") {
  std::ostringstream text;
  nlohmann::json summary;
  kit::Report report(text, summary);
  report.say("reference", "error {max_error:.3g} m after {steps} steps, {status}\n",
             {{"max_error", 1.234567e-9}, {"steps", 42L}, {"status", std::string("finished")}});
  CHECK(text.str() == "error 1.23e-09 m after 42 steps, finished\n");
  CHECK(summary["reference"]["max_error"].get<double>() == 1.234567e-9);
  CHECK(summary["reference"]["steps"].get<long>() == 42);
  CHECK(summary["reference"]["steps"].is_number_integer());
  report.say("roundoff/explicit_float", "{best_dt:.2e}\n", {{"best_dt", 5.6e-5}});
  CHECK(summary["roundoff"]["explicit_float"]["best_dt"].get<double>() == 5.6e-5);
  report.say("", "top {n}\n", {{"n", 3L}});
  CHECK(summary["n"].get<long>() == 3);
}

TEST_CASE("a reported table prints the formatted cells and appends one JSON object per row") {
  std::ostringstream text;
  nlohmann::json summary;
  kit::Report report(text, summary);
  auto table = report.table("samples", {{"k", "k"}, {"t [s]", "t", "{:.2f}"}, {"", "hidden"}, {"ok", "match", "check"},
                                        {"accepted", "accepted"}});
  table.row({0L, 0.0, 7.5, true, 3L});
  table.row({1L, 0.125, 8.5, false, std::monostate{}}, false);  // JSON only
  table.print();
  CHECK(text.str() == "k  t [s]  ok  accepted\n----------------------\n0   0.00   ✓         3\n");
  REQUIRE(summary["samples"].size() == 2);
  CHECK(summary["samples"][1]["t"].get<double>() == 0.125);
  CHECK(summary["samples"][1]["hidden"].get<double>() == 8.5);
  CHECK(summary["samples"][1]["match"].get<bool>() == false);
  CHECK(summary["samples"][1]["accepted"].is_null());
  CHECK_THROWS_AS(table.row({1L}), std::invalid_argument);
}

TEST_CASE("format_value: yes/no for booleans by default, a dash for a missing value") {
  CHECK(kit::format_value(true, "{}") == "yes");
  CHECK(kit::format_value(false, "check") == "✗");
  CHECK(kit::format_value(std::monostate{}, "{:.3e}") == "-");
  CHECK(kit::format_value(0.00123, "{:.2e}") == "1.23e-03");
}
