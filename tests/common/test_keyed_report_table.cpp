// A reported table keyed by row (keyed_report_table.hpp): one call prints a row and stores it.
#include <sstream>

#include <catch2/catch.hpp>

#include <kit/keyed_report_table.hpp>

TEST_CASE("a keyed table prints its rows and stores each under its key, labels printed only") {
  std::ostringstream text;
  nlohmann::json summary;
  kit::Report report(text, summary);
  kit::KeyedReportTable table(report, "critical", {{"scheme", ""}, {"Δt [s]", "measured", "{:.2e}"},
                                                   {"", "hidden"}, {"ok", "match", "check"}});
  table.row("rk4", {std::string("RK4"), 0.2828, 7L, true});
  table.row("explicit_euler", {std::string("explicit Euler"), std::monostate{}, 8L, false}, false);  // JSON
  table.print();
  CHECK(text.str() == "scheme    Δt [s]  ok\n--------------------\n   RK4  2.83e-01   ✓\n");
  CHECK(summary["critical"]["rk4"]["measured"].get<double>() == 0.2828);
  CHECK(summary["critical"]["rk4"]["hidden"].get<long>() == 7);
  CHECK_FALSE(summary["critical"]["rk4"].contains(""));  // the label is not stored
  CHECK(summary["critical"]["explicit_euler"]["measured"].is_null());
  CHECK(summary["critical"]["explicit_euler"]["match"].get<bool>() == false);
  CHECK_THROWS_AS(table.row("midpoint", {1L}), std::invalid_argument);
}

TEST_CASE("a keyed table adds its rows to what the section already holds") {
  std::ostringstream text;
  nlohmann::json summary;
  kit::Report report(text, summary);
  report.json("roundoff/explicit_double") = {{"dt", {0.1, 0.01}}};
  kit::KeyedReportTable table(report, "roundoff", {{"best Δt [s]", "best_dt", "{:.3g}"}});
  table.row("explicit_double", {0.01});
  CHECK(summary["roundoff"]["explicit_double"]["dt"].size() == 2);
  CHECK(summary["roundoff"]["explicit_double"]["best_dt"].get<double>() == 0.01);
}
