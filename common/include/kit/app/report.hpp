#pragma once
// The report layer: every number a chapter prints comes from the call that also writes it to
// the --json summary, so the text and the JSON cannot drift apart.
//   report.say("reference", "GSL rk8pd: max |x - exact| = {max_error:.3g} m", {{"max_error", e}});
//     prints the sentence and sets summary["reference"]["max_error"] = e;
//   auto table = report.table("samples", {{"k", "k"}, {"t [s]", "t", "{:.4f}"}});
//   table.row({k, t});  ... table.print();
//     prints the table and appends {"k": k, "t": t} to summary["samples"] for every row;
//   table.row("rk4", {...}) stores a row by name instead, summary["samples"]["rk4"] = {...},
//   and table.append("GSL rkck", {...}) appends it to the array summary["samples"]["GSL rkck"].
#include <initializer_list>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include <kit/app/table.hpp>
#include <kit/base/not_implemented.hpp>

namespace kit {

/// One reported value. A long stays a whole number in the JSON; std::monostate prints "-" and
/// is stored as null (a count a peer does not report, say).
using ReportValue = std::variant<std::monostate, bool, long, double, std::string>;

/// The value, or "-" and null when there is none (a step count a peer does not report).
ReportValue optional_value(const std::optional<double>& value);
ReportValue optional_value(const std::optional<long>& value);
/// values[k], or "-" and null past its end (a run that has not been made: its exercise waits).
template <class T>
ReportValue value_at(const std::vector<T>& values, std::size_t k) {
  if (k >= values.size()) return std::monostate{};
  return static_cast<T>(values[k]);
}

/// A named value: `key` is its JSON key and its name in a sentence's {key:format} field.
struct Field {
  std::string key;
  ReportValue value;
};

/// A column of a reported table.
struct Column {
  std::string header;         ///< printed header with unit, e.g. "Δt [s]"; empty: JSON only
  std::string key;            ///< JSON key of the value in every row object; empty: printed only
                              ///< (a label such as a display name, when rows are stored by name)
  std::string format = "{}";  ///< fmt format of the printed cell: "{:.3e}", "{:.4f}"; "check" prints ✓/✗,
                              ///< "yes/no" prints yes/no
};

/// The text of `value` as `format` prints it (see Column::format). A string prints as it is
/// whatever the format; a non-finite double prints "overflow" or "undefined", never inf or nan.
std::string format_value(const ReportValue& value, const std::string& format);
/// The JSON of `value`.
nlohmann::json to_json(const ReportValue& value);

class Report;

/// A table being filled: print() shows it (unless the report is silent, or it has no printed
/// row); every row is in the JSON already.
class ReportTable {
 public:
  /// One row, a value per column, in the columns' order. `printed` = false keeps the row out of
  /// the text (a thinned table) but not out of the JSON.
  void row(std::vector<ReportValue> values, bool printed = true);
  /// One row stored by name, section[name][key] = value for each column (beside what the object
  /// there already holds). The name is one key, whatever it contains ("stiff, ω = 1e6 rad/s").
  void row(std::string_view name, std::vector<ReportValue> values, bool printed = true);
  /// The same at a nested place: row_at({"rk4", "1e-03"}, …) stores section["rk4"]["1e-03"].
  void row_at(const std::vector<std::string>& path, std::vector<ReportValue> values, bool printed = true);
  /// One row appended to the array section[name].
  void append(std::string_view name, std::vector<ReportValue> values, bool printed = true);
  void print() const;

 private:
  friend class Report;
  ReportTable(std::ostream& text, nlohmann::json& rows, std::vector<Column> columns);
  /// The row's JSON object; its printed cells go to the table when `printed`.
  nlohmann::json record(std::vector<ReportValue> values, bool printed);
  nlohmann::json& slot(const std::vector<std::string>& path);
  std::ostream* text_;
  nlohmann::json* rows_;
  std::vector<Column> columns_;
  Table table_;
};

class Report {
 public:
  /// Text goes to `text`; values go into `summary`.
  Report(std::ostream& text, nlohmann::json& summary) : text_(&text), summary_(&summary) {}

  /// Prints `sentence`, in which "{key}" or "{key:spec}" stands for a field's value (fmt
  /// syntax), and stores every field under summary[section][key]. `section` is a JSON pointer
  /// path without the leading slash ("" = top level, "reference", "roundoff/explicit_float").
  void say(std::string_view section, std::string_view sentence, const std::vector<Field>& fields);
  /// Stores fields without printing them (values the text shows in a figure or not at all).
  void store(std::string_view section, const std::vector<Field>& fields);
  /// Prints text that holds no number.
  void print(std::string_view text) { *text_ << text; }
  /// A table whose rows are printed and appended to summary[section] (an array of objects).
  ReportTable table(std::string_view section, std::vector<Column> columns);
  /// The JSON node at `section`, for what a row or a field cannot hold (arrays of a sweep).
  nlohmann::json& json(std::string_view section);

  /// Runs one part of a chapter, `fn()`: a lecture section or one method inside it. When it
  /// needs an exercise the student has not written yet (kit::NotImplemented), the report says
  /// which part waits for which exercise ("[skipped] …" in the text, summary["skipped"] in the
  /// JSON) and the chapter goes on: a student sees every part that their code already runs.
  /// Returns fn's result, or nullopt when skipped (true/false for a part that returns nothing).
  template <class F>
  auto attempt(const std::string& part, F&& fn) {
    using R = std::invoke_result_t<F>;
    try {
      if constexpr (std::is_void_v<R>) {
        fn();
        return true;
      } else {
        return std::optional<R>(fn());
      }
    } catch (const NotImplemented& waiting) {
      skipped(part, waiting.what());
      if constexpr (std::is_void_v<R>) {
        return false;
      } else {
        return std::optional<R>();
      }
    }
  }

 private:
  void skipped(const std::string& part, const std::string& why);

  std::ostream* text_;
  nlohmann::json* summary_;
};

}  // namespace kit
