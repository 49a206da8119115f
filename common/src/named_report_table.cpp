#include <kit/named_report_table.hpp>

#include <string>
#include <utility>

namespace kit {

NamedReportTable::NamedReportTable(std::ostream& text, nlohmann::json& section, std::vector<Column> columns)
    : rows_(nlohmann::json::array()), scratch_(text, rows_), table_(scratch_.table("", std::move(columns))),
      section_(&section) {}

nlohmann::json& NamedReportTable::slot(std::string_view name) {
  std::string path(1, '/');
  path.append(name.data(), name.size());
  return (*section_)[nlohmann::json::json_pointer(path)];
}

nlohmann::json NamedReportTable::last_row(std::vector<ReportValue> values, bool printed) {
  table_.row(std::move(values), printed);
  nlohmann::json object = std::move(rows_.back());
  rows_.erase(rows_.end() - 1);
  return object;
}

void NamedReportTable::row(std::string_view name, std::vector<ReportValue> values, bool printed) {
  slot(name) = last_row(std::move(values), printed);
}

void NamedReportTable::append(std::string_view name, std::vector<ReportValue> values, bool printed) {
  nlohmann::json object = last_row(std::move(values), printed);
  slot(name).push_back(std::move(object));
}

}  // namespace kit
