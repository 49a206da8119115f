#include "toml_read.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include <kit/base/usage.hpp>

namespace kit::scene_toml {

std::string_view kind(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a floating-point number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    default:
      return "nothing";
  }
}

namespace {
/// The value written out in full; show() cuts it short.
std::string written(const toml::node& n) {
  if (const auto* v = n.as_integer()) return fmt::format("{}", v->get());
  if (const auto* f = n.as_floating_point()) return fmt::format("{}", f->get());
  if (const auto* b = n.as_boolean()) return fmt::format("{}", b->get());
  if (const auto* str = n.as_string()) return fmt::format("\"{}\"", str->get());
  if (const auto* a = n.as_array()) {
    std::string s(1, '[');
    for (std::size_t i = 0; i < a->size(); ++i) s += (i ? ", " : "") + written(*a->get(i));
    return s + ']';
  }
  if (const auto* t = n.as_table()) {
    std::string s(1, '{');
    bool first = true;
    for (const auto& kv : *t) {
      s += fmt::format("{} {} = {}", first ? "" : ",", kv.first.str(), written(kv.second));
      first = false;
    }
    return s + " }";
  }
  std::ostringstream os;
  n.visit([&os](const auto& x) { os << x; });
  return os.str();
}
}  // namespace

std::string show(const toml::node& n) {
  // One line, cut short: a message quotes the value, not a whole table.
  constexpr std::size_t longest = 80;
  std::string s = written(n);
  if (s.size() > longest) s = s.substr(0, longest - 3) + "...";
  return s;
}

std::string join(std::initializer_list<std::string_view> words) {
  return join(std::vector<std::string>(words.begin(), words.end()));
}

std::string join(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : ", ") + w;
  return s;
}

std::string read_text(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw UsageError(fmt::format("cannot read scene file {}: {}", file.string(),
                                 std::filesystem::exists(file, ec) ? "not a regular file" : "no such file"));
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in || !text) throw UsageError(fmt::format("cannot read scene file {}: read failed", file.string()));
  return text.str();
}

toml::table Reader::parse(std::string_view text) const {
  try {
    return toml::parse(text, file_);
  } catch (const toml::parse_error& e) {
    fail_at(e.source(),
            fmt::format("TOML syntax error at column {}: {}", e.source().begin.column, e.description()));
  }
}

void Reader::fail_at(const toml::source_region& where, std::string_view what) const {
  // The root table of a document has no line of its own: its mistakes are on line 1.
  const auto line = std::max<toml::source_index>(where.begin.line, 1);
  throw UsageError(fmt::format("{}:{}: {}", file_, line, what));
}

void Reader::bad(const toml::node& n, const std::string& key, std::string_view what) const {
  fail(n, fmt::format("{} = {}: {}", key, show(n), what));
}

double Reader::real(const toml::node& n, const std::string& key, const RealRange& range) const {
  double x = 0;
  if (const auto* f = n.as_floating_point())
    x = f->get();
  else if (const auto* i = n.as_integer())  // TOML's 2 where 2.0 is meant
    x = static_cast<double>(i->get());
  else
    bad(n, key, fmt::format("expected a number, got {}", kind(n)));
  if (!range.contains(x)) bad(n, key, "must be " + range.describe());
  return x;
}

long Reader::integer(const toml::node& n, const std::string& key, long long lo, long long hi) const {
  const auto* i = n.as_integer();
  if (!i) bad(n, key, fmt::format("expected an integer, got {}", kind(n)));
  const long long x = i->get();
  if (x < lo || x > hi)
    bad(n, key,
        hi == no_limit ? fmt::format("must be an integer >= {}", lo)
                       : fmt::format("must be an integer in [{}, {}]", lo, hi));
  return static_cast<long>(x);
}

std::string Reader::string(const toml::node& n, const std::string& key) const {
  const auto* s = n.as_string();
  if (!s) bad(n, key, fmt::format("expected a string, got {}", kind(n)));
  return s->get();
}

bool Reader::boolean(const toml::node& n, const std::string& key) const {
  const auto* b = n.as_boolean();
  if (!b) bad(n, key, fmt::format("expected true or false, got {}", kind(n)));
  return b->get();
}

std::size_t Reader::choice(const toml::node& n, const std::string& key,
                           const std::vector<std::string>& names) const {
  const std::string s = string(n, key);
  const auto it = std::find(names.begin(), names.end(), s);
  if (it == names.end()) bad(n, key, "must be one of " + join(names));
  return static_cast<std::size_t>(std::distance(names.begin(), it));
}

const toml::array& Reader::array(const toml::node& n, const std::string& key, std::size_t size,
                                 std::string_view elements, std::string_view components) const {
  const auto* a = n.as_array();
  if (!a)
    bad(n, key, fmt::format("expected an array of {} {} [{}], got {}", size, elements, components, kind(n)));
  if (a->size() != size)
    bad(n, key,
        fmt::format("expected an array of {} {} [{}], got {} elements", size, elements, components,
                    a->size()));
  return *a;
}

std::array<double, 3> Reader::vec3(const toml::node& n, const std::string& key, const RealRange& range,
                                   std::string_view components) const {
  const toml::array& a = array(n, key, 3, "numbers", components);
  std::array<double, 3> v{};
  for (std::size_t i = 0; i < 3; ++i) v[i] = real(*a.get(i), fmt::format("{}[{}]", key, i), range);
  return v;
}

std::string Section::key(std::string_view k) const {
  return path_.empty() ? std::string(k) : path_ + "." + std::string(k);
}

void Section::only(std::initializer_list<std::string_view> allowed) const {
  for (const auto& kv : table_) {
    const std::string_view k = kv.first.str();
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
      r_.fail_at(kv.first.source(), fmt::format("unknown key '{}' (allowed: {})", key(k), join(allowed)));
  }
}

void Section::missing(std::string_view k, std::string_view why) const {
  r_.fail_at(table_.source(), fmt::format("missing key '{}': {}", key(k), why));
}

std::optional<double> Section::real(std::string_view k, const RealRange& range) const {
  if (const auto* n = find(k)) return r_.real(*n, key(k), range);
  return std::nullopt;
}
std::optional<long> Section::integer(std::string_view k, long long lo, long long hi) const {
  if (const auto* n = find(k)) return r_.integer(*n, key(k), lo, hi);
  return std::nullopt;
}
std::optional<std::string> Section::string(std::string_view k) const {
  if (const auto* n = find(k)) return r_.string(*n, key(k));
  return std::nullopt;
}
std::optional<bool> Section::boolean(std::string_view k) const {
  if (const auto* n = find(k)) return r_.boolean(*n, key(k));
  return std::nullopt;
}
std::optional<std::size_t> Section::choice(std::string_view k, const std::vector<std::string>& names) const {
  if (const auto* n = find(k)) return r_.choice(*n, key(k), names);
  return std::nullopt;
}
std::optional<std::array<double, 3>> Section::vec3(std::string_view k, const RealRange& range,
                                                   std::string_view components) const {
  if (const auto* n = find(k)) return r_.vec3(*n, key(k), range, components);
  return std::nullopt;
}

std::optional<Section> Section::sub(std::string_view k) const {
  const auto* n = find(k);
  if (!n) return std::nullopt;
  const auto* t = n->as_table();
  if (!t) r_.bad(*n, key(k), fmt::format("expected a table, got {}", kind(*n)));
  return Section(r_, *t, key(k));
}

}  // namespace kit::scene_toml
