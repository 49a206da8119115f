#include <kit/app/report.hpp>

#include <cmath>
#include <regex>
#include <stdexcept>

#include <fmt/args.h>
#include <fmt/format.h>

namespace kit {

std::string format_value(const ReportValue& value, const std::string& format) {
  if (std::holds_alternative<std::monostate>(value)) return "-";
  if (const bool* b = std::get_if<bool>(&value)) {
    if (format == "check") return *b ? "✓" : "✗";
    return *b ? "yes" : "no";
  }
  if (const double* d = std::get_if<double>(&value); d && !std::isfinite(*d))
    return std::isnan(*d) ? "undefined" : (*d > 0 ? "overflow" : "-overflow");  // never "inf" or "-nan"
  if (const std::string* text = std::get_if<std::string>(&value))
    return *text;  // a label ignores number specs
  return std::visit(
      [&](const auto& v) -> std::string {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, long> || std::is_same_v<V, double>) {
          return fmt::format(fmt::runtime(format), v);
        } else {
          return {};
        }
      },
      value);
}

ReportValue optional_value(const std::optional<double>& value) {
  if (value) return *value;
  return std::monostate{};
}
ReportValue optional_value(const std::optional<long>& value) {
  if (value) return *value;
  return std::monostate{};
}

nlohmann::json to_json(const ReportValue& value) {
  return std::visit(
      [](const auto& v) -> nlohmann::json {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, std::monostate>) {
          return nullptr;
        } else {
          return v;
        }
      },
      value);
}

ReportTable::ReportTable(std::ostream& text, nlohmann::json& rows, std::vector<Column> columns)
    : text_(&text), rows_(&rows), columns_(std::move(columns)), table_([&] {
        std::vector<std::string> headers;
        for (const auto& c : columns_)
          if (!c.header.empty()) headers.push_back(c.header);
        return headers;
      }()) {}

nlohmann::json ReportTable::record(std::vector<ReportValue> values, bool printed) {
  if (values.size() != columns_.size())
    throw std::invalid_argument(
        fmt::format("report row has {} values for {} columns", values.size(), columns_.size()));
  nlohmann::json object = nlohmann::json::object();
  std::vector<std::string> cells;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!columns_[i].key.empty()) object[columns_[i].key] = to_json(values[i]);
    if (!columns_[i].header.empty()) cells.push_back(format_value(values[i], columns_[i].format));
  }
  if (printed) table_.add_row(std::move(cells));
  return object;
}

nlohmann::json& ReportTable::slot(const std::vector<std::string>& path) {
  nlohmann::json* node = rows_;
  for (const auto& part : path) node = &(*node)[part];  // literal keys: "rad/s" stays one key
  return *node;
}

void ReportTable::row(std::vector<ReportValue> values, bool printed) {
  nlohmann::json object = record(std::move(values), printed);
  if (!rows_->is_array()) *rows_ = nlohmann::json::array();
  rows_->push_back(std::move(object));
}

void ReportTable::row(std::string_view name, std::vector<ReportValue> values, bool printed) {
  row_at({std::string(name)}, std::move(values), printed);
}

void ReportTable::row_at(const std::vector<std::string>& path, std::vector<ReportValue> values,
                         bool printed) {
  nlohmann::json& target = slot(path);
  nlohmann::json object = record(std::move(values), printed);
  if (target.is_object()) {
    target.update(object);  // beside what the section already holds there (a sweep's arrays)
  } else {
    target = std::move(object);
  }
}

void ReportTable::append(std::string_view name, std::vector<ReportValue> values, bool printed) {
  nlohmann::json object = record(std::move(values), printed);
  slot({std::string(name)}).push_back(std::move(object));
}

void ReportTable::print() const {
  if (!table_.empty()) table_.print(*text_);  // no rows (every method waits for its exercise): no header
}

nlohmann::json& Report::json(std::string_view section) {
  if (section.empty()) return *summary_;
  std::string path(1, '/');
  path.append(section.data(), section.size());
  return (*summary_)[nlohmann::json::json_pointer(path)];
}

void Report::store(std::string_view section, const std::vector<Field>& fields) {
  nlohmann::json& node = json(section);
  for (const auto& f : fields) node[f.key] = to_json(f.value);
}

void Report::say(std::string_view section, std::string_view sentence, const std::vector<Field>& fields) {
  // A missing value or a non-finite double takes the words format_value gives it ("-",
  // "overflow", "undefined") whatever the field's format, so a sentence never prints inf or nan.
  std::string text(sentence);
  fmt::dynamic_format_arg_store<fmt::format_context> args;
  for (const auto& f : fields) {
    const double* d = std::get_if<double>(&f.value);
    if (std::holds_alternative<std::monostate>(f.value) || (d && !std::isfinite(*d))) {
      const std::regex field("\\{" + f.key + "(:[^}]*)?\\}");
      text = std::regex_replace(text, field, format_value(f.value, "{}"));
      continue;
    }
    std::visit(
        [&](const auto& v) {
          using V = std::decay_t<decltype(v)>;
          if constexpr (!std::is_same_v<V, std::monostate>) args.push_back(fmt::arg(f.key.c_str(), v));
        },
        f.value);
  }
  *text_ << fmt::vformat(text, args);
  store(section, fields);
}

ReportTable Report::table(std::string_view section, std::vector<Column> columns) {
  return ReportTable(*text_, json(section), std::move(columns));
}

void Report::skipped(const std::string& part, const std::string& why) {
  print(fmt::format("[skipped] {}: {}\n", part, why));  // words only: the JSON has the same
  (*summary_)["skipped"].push_back({{"section", part}, {"reason", why}});
}

}  // namespace kit
