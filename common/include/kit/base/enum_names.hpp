#pragma once
// One name table an enumeration: each value with the name flags, scene files and summaries use
// ("symplectic") and the name figures and tables show ("symplectic Euler"). Printing a value,
// parsing a name and listing a flag's choices (ChapterApp::add_choice) all read the table, so
// none can disagree with another, and a new value is one new row.
//
//   inline constexpr auto integrator_names = enum_names<Integrator>({
//       {Integrator::explicit_euler, "euler", "explicit Euler"}, ...});
//   static_assert(integrator_names.in_order());
//
// The rows list the values in their declared order (in_order(), checked at compile time where a
// table is defined), so a value finds its row by its index.
#include <array>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace kit {

template <typename Enum>
struct EnumName {
  Enum value;
  const char* flag;     ///< in flags, scene files and --json summaries
  const char* display;  ///< in figures, tables and messages
};

template <typename Enum, std::size_t N>
struct EnumNames {
  std::array<EnumName<Enum>, N> rows;

  /// True when row i holds the value whose index is i, for every i: what row() relies on.
  constexpr bool in_order() const {
    for (std::size_t i = 0; i < N; ++i)
      if (static_cast<std::size_t>(rows[i].value) != i) return false;
    return true;
  }
  constexpr const EnumName<Enum>& row(Enum value) const {
    const auto i = static_cast<std::size_t>(value);
    if (i >= N) throw std::out_of_range("an enumeration value without a row in its name table");
    return rows[i];
  }
  constexpr const char* flag(Enum value) const { return row(value).flag; }
  constexpr const char* display(Enum value) const { return row(value).display; }
  /// The value a flag name stands for, or nothing when no row has that name.
  constexpr std::optional<Enum> parse(std::string_view flag) const {
    for (const auto& r : rows)
      if (flag == r.flag) return r.value;
    return std::nullopt;
  }
  /// Every flag name, in the table's order: a flag's choices.
  std::vector<std::string> flags() const {
    std::vector<std::string> out;
    for (const auto& r : rows) out.emplace_back(r.flag);
    return out;
  }
  /// Every value, in the table's order: `for (Integrator i : integrator_names.all())`.
  constexpr std::array<Enum, N> all() const {
    std::array<Enum, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = rows[i].value;
    return out;
  }
};

/// A table from a braced list of rows, its size deduced.
template <typename Enum, std::size_t N>
constexpr EnumNames<Enum, N> enum_names(const EnumName<Enum> (&rows)[N]) {
  EnumNames<Enum, N> table{};
  for (std::size_t i = 0; i < N; ++i) table.rows[i] = rows[i];
  return table;
}

}  // namespace kit
