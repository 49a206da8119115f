#pragma once
// A reported table whose rows the JSON keeps by name rather than in one array, for summaries
// read as summary["orders"]["rk4"] or summary["work_precision"]["GSL rkck"][i]:
//   kit::NamedReportTable orders(app.text(), app.report().json("orders"), {{"scheme", "scheme"}, ...});
//   orders.row("rk4", {...});        // summary["orders"]["rk4"] = {column key: value, ...}
//   orders.append("GSL rkck", {...}); // appends the same object to summary[...]["GSL rkck"]
//   orders.print();
// Each row's printed cells and its JSON come from ReportTable (report.hpp), in one call.
#include <ostream>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include <kit/report.hpp>

namespace kit {

class NamedReportTable {
 public:
  /// Rows are printed to `text` and stored under `section` (e.g. app.report().json("orders")).
  NamedReportTable(std::ostream& text, nlohmann::json& section, std::vector<Column> columns);
  NamedReportTable(const NamedReportTable&) = delete;
  NamedReportTable& operator=(const NamedReportTable&) = delete;

  /// Stores the row as section[name]; a name with slashes nests ("rk4/1e-03"; as in a JSON
  /// pointer, an all-digit part indexes an array). `printed` = false
  /// keeps it out of the text, not out of the JSON.
  void row(std::string_view name, std::vector<ReportValue> values, bool printed = true);
  /// Appends the row to the array section[name].
  void append(std::string_view name, std::vector<ReportValue> values, bool printed = true);
  void print() const { table_.print(); }

 private:
  nlohmann::json& slot(std::string_view name);
  nlohmann::json last_row(std::vector<ReportValue> values, bool printed);
  nlohmann::json rows_;  // ReportTable appends here; each row then moves to its name
  Report scratch_;
  ReportTable table_;
  nlohmann::json* section_;
};

}  // namespace kit
