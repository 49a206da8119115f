#pragma once
// Plain-text tables for the chapters' printed results.
#include <iosfwd>
#include <string>
#include <vector>

namespace kit {

/// Columns are right-aligned and sized to their widest cell (UTF-8 aware).
class Table {
 public:
  explicit Table(std::vector<std::string> headers);
  void add_row(std::vector<std::string> cells);
  void print(std::ostream& out) const;
  bool empty() const { return rows_.empty(); }

 private:
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
};

/// Scientific notation with `digits` significant digits: sci(0.00123, 3) == "1.23e-03".
std::string sci(double value, int digits = 3);
/// Fixed notation with `decimals` decimals.
std::string fixed(double value, int decimals);

}  // namespace kit
