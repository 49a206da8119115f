// A table whose rows the JSON keeps by name: printed cells and JSON from one call, as ReportTable.
#include <sstream>

#include <catch2/catch.hpp>

#include <kit/named_report_table.hpp>

TEST_CASE("a named table prints its rows and stores each under its name, nested by slashes or appended") {
  std::ostringstream text;
  nlohmann::json summary;
  kit::Report report(text, summary);
  kit::NamedReportTable table(text, report.json("orders"), {{"scheme", "scheme"}, {"order", "fitted", "{:.2f}"}, {"", "points"}});
  table.row("rk4", {std::string("RK4"), 3.9923, 8L});
  table.row("midpoint/1e-03", {std::string("midpoint"), 1.9988, 28L}, false);  // JSON only
  table.append("list", {std::string("a"), 1.0, 1L});
  table.append("list", {std::string("b"), 2.0, 2L});
  table.print();
  CHECK(text.str() == "scheme  order\n-------------\n   RK4   3.99\n     a   1.00\n     b   2.00\n");
  CHECK(summary["orders"]["rk4"]["fitted"].get<double>() == 3.9923);
  CHECK(summary["orders"]["rk4"]["points"].get<long>() == 8);
  CHECK(summary["orders"]["midpoint"]["1e-03"]["scheme"] == "midpoint");
  REQUIRE(summary["orders"]["list"].size() == 2);
  CHECK(summary["orders"]["list"][1]["scheme"] == "b");
  CHECK_THROWS_AS(table.row("x", {1L}), std::invalid_argument);
}
