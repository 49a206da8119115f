#pragma once
// Reading a scene file with toml++, shared by the scene loaders of chapter 5 (sprites) and
// chapters 6–7 (cloth). Every mistake is a UsageError that names the file, the line, the full
// dotted key, the bad value and what is allowed:
//   scenes/flag.toml:26: springs.shear.stiffness = -1: must be a finite number in (0, 1000000000]
// A private header of kit_common (not under include/): toml++ is a private dependency of the
// library, so nothing outside common/src may see its types.
#include <array>
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include <kit/base/enum_names.hpp>
#include <kit/base/real_range.hpp>
#include <kit/base/vec3.hpp>

namespace kit::scene_toml {

/// An integer bound meaning "no upper limit".
inline constexpr long long no_limit = std::numeric_limits<long long>::max();

/// [−bound, bound]: a coordinate or a rate of either sign.
inline RealRange symmetric(double bound) { return between(-bound, bound); }

/// "a string", "an integer": what a node is, for "expected X, got Y".
std::string_view kind(const toml::node& n);
/// The value as the scene file would write it, on one line, cut short when long.
std::string show(const toml::node& n);
/// Three numbers a scene file gave (Section::vec3) as a point or direction.
inline Vec3 to_vec3(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
/// "a, b, c".
std::string join(std::initializer_list<std::string_view> words);
std::string join(const std::vector<std::string>& words);

/// The whole file as text; UsageError "cannot read scene file ..." when it cannot be read.
std::string read_text(const std::filesystem::path& file);

/// Turns a position in the file into the message's "file:line: " prefix, and reads one value.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  /// Parses `text` as TOML; a syntax error is a UsageError at its line.
  toml::table parse(std::string_view text) const;

  [[noreturn]] void fail_at(const toml::source_region& where, std::string_view what) const;
  [[noreturn]] void fail(const toml::node& n, std::string_view what) const { fail_at(n.source(), what); }
  /// "file:line: key = value: what".
  [[noreturn]] void bad(const toml::node& n, const std::string& key, std::string_view what) const;

  /// A number in `range`; TOML integers are accepted where a real is meant (2 for 2.0).
  double real(const toml::node& n, const std::string& key, const RealRange& range) const;
  long integer(const toml::node& n, const std::string& key, long long lo, long long hi) const;
  std::string string(const toml::node& n, const std::string& key) const;
  bool boolean(const toml::node& n, const std::string& key) const;
  /// Index of the string's value in `names`.
  std::size_t choice(const toml::node& n, const std::string& key,
                     const std::vector<std::string>& names) const;
  /// Three numbers, each in `range`; `components` names them for the message ("x, y, z").
  std::array<double, 3> vec3(const toml::node& n, const std::string& key, const RealRange& range,
                             std::string_view components) const;
  /// The array at `n`, of exactly `size` elements; `elements` ("numbers", "integers") and
  /// `components` ("x, y, z") say what it holds, for the message.
  const toml::array& array(const toml::node& n, const std::string& key, std::size_t size,
                           std::string_view elements, std::string_view components) const;

  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

/// One TOML table and its dotted key ("emitter[0]", "springs.bend", "" for the document).
class Section {
 public:
  Section(const Reader& reader, const toml::table& table, std::string path)
      : r_(reader), table_(table), path_(std::move(path)) {}

  std::string key(std::string_view k) const;
  const toml::node* find(std::string_view k) const { return table_.get(k); }
  const toml::table& table() const { return table_; }
  const Reader& reader() const { return r_; }

  /// Refuses every key not in `allowed`: a misspelt key would otherwise be silently ignored.
  void only(std::initializer_list<std::string_view> allowed) const;
  [[noreturn]] void missing(std::string_view k, std::string_view why) const;

  // Each returns nullopt when the key is absent, and throws when it is present but wrong.
  std::optional<double> real(std::string_view k, const RealRange& range) const;
  std::optional<long> integer(std::string_view k, long long lo, long long hi) const;
  std::optional<std::string> string(std::string_view k) const;
  std::optional<bool> boolean(std::string_view k) const;
  std::optional<std::size_t> choice(std::string_view k, const std::vector<std::string>& names) const;
  /// The value of an enumeration its table names (kit/base/enum_names.hpp).
  template <typename Enum, std::size_t N>
  std::optional<Enum> choice(std::string_view k, const EnumNames<Enum, N>& names) const {
    if (const auto i = choice(k, names.flags())) return names.rows[*i].value;
    return std::nullopt;
  }
  std::optional<std::array<double, 3>> vec3(std::string_view k, const RealRange& range,
                                            std::string_view components = "x, y, z") const;
  /// The sub-table at `k`, or nullopt when the file leaves it out.
  std::optional<Section> sub(std::string_view k) const;

 private:
  const Reader& r_;
  const toml::table& table_;
  std::string path_;
};

}  // namespace kit::scene_toml
