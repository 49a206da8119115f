#include <kit/keyed_report_table.hpp>

#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

namespace kit {
namespace {
std::vector<std::string> printed_headers(const std::vector<Column>& columns) {
  std::vector<std::string> headers;
  for (const auto& c : columns)
    if (!c.header.empty()) headers.push_back(c.header);
  return headers;
}
}  // namespace

KeyedReportTable::KeyedReportTable(Report& report, std::string section, std::vector<Column> columns)
    : report_(&report),
      section_(std::move(section)),
      columns_(std::move(columns)),
      table_(printed_headers(columns_)) {}

void KeyedReportTable::row(const std::string& key, std::vector<ReportValue> values, bool printed) {
  if (values.size() != columns_.size())
    throw std::invalid_argument(
        fmt::format("report row '{}' has {} values for {} columns", key, values.size(), columns_.size()));
  nlohmann::json& object = report_->json(section_)[key];
  std::vector<std::string> cells;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!columns_[i].key.empty()) object[columns_[i].key] = to_json(values[i]);
    if (!columns_[i].header.empty()) cells.push_back(format_value(values[i], columns_[i].format));
  }
  if (printed) table_.add_row(std::move(cells));
}

void KeyedReportTable::print() const {
  std::ostringstream text;
  table_.print(text);
  report_->print(text.str());
}

}  // namespace kit
