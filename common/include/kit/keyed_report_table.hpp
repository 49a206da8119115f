#pragma once
// A reported table whose JSON is an object keyed by row, not an array of rows: for results
// looked up by name (a scheme, a spring, a curve), e.g. summary["critical"]["rk4"]["measured"].
// Like Report::table (report.hpp), one call prints a row and stores the same values:
//   kit::KeyedReportTable table(report, "critical", {{"scheme", ""}, {"Δt [s]", "measured", "{:.5e}"}});
//   table.row("rk4", {std::string("RK4"), 0.2828});  // summary["critical"]["rk4"]["measured"] = 0.2828
//   table.print();
#include <string>
#include <vector>

#include <kit/report.hpp>
#include <kit/table.hpp>

namespace kit {

class KeyedReportTable {
 public:
  /// Rows go to summary[section][row key][column key]. A column with an empty header is stored
  /// only (as in Report::table); a column with an empty key is printed only: a label, such as a
  /// display name, that holds no number.
  KeyedReportTable(Report& report, std::string section, std::vector<Column> columns);

  /// One row, a value per column in the columns' order, stored under `key`. `printed` = false
  /// keeps it out of the text, not out of the JSON.
  void row(const std::string& key, std::vector<ReportValue> values, bool printed = true);
  /// Prints the printed rows (nothing when the report is silent).
  void print() const;

 private:
  Report* report_;
  std::string section_;
  std::vector<Column> columns_;
  Table table_;
};

}  // namespace kit
