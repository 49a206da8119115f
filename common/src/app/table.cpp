#include <kit/app/table.hpp>

#include <algorithm>
#include <ostream>
#include <stdexcept>

#include <fmt/format.h>

namespace kit {
namespace {
// Columns on a terminal: count code points, not bytes ("Δt", "✓").
std::size_t display_width(const std::string& s) {
  return static_cast<std::size_t>(std::count_if(
      s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}
}  // namespace

Table::Table(std::vector<std::string> headers) : headers_(std::move(headers)) {}

void Table::add_row(std::vector<std::string> cells) {
  if (cells.size() != headers_.size())
    throw std::invalid_argument(
        fmt::format("table row has {} cells for {} columns", cells.size(), headers_.size()));
  rows_.push_back(std::move(cells));
}

void Table::print(std::ostream& out) const {
  std::vector<std::size_t> width(headers_.size());
  for (std::size_t c = 0; c < headers_.size(); ++c) {
    width[c] = display_width(headers_[c]);
    for (const auto& row : rows_) width[c] = std::max(width[c], display_width(row[c]));
  }
  auto print_row = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) {
      out << (c ? "  " : "") << std::string(width[c] - display_width(cells[c]), ' ') << cells[c];
    }
    out << '\n';
  };
  print_row(headers_);
  std::size_t total = 0;
  for (auto w : width) total += w;
  out << std::string(total + 2 * (width.size() - 1), '-') << '\n';
  for (const auto& row : rows_) print_row(row);
}

std::string sci(double value, int digits) { return fmt::format("{:.{}e}", value, digits - 1); }
std::string fixed(double value, int decimals) { return fmt::format("{:.{}f}", value, decimals); }

}  // namespace kit
