#include <kit/base/whole_number.hpp>

#include <algorithm>
#include <cctype>
#include <climits>
#include <string>

namespace kit {
namespace {

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// The run of digits at `at`, moving `at` past it.
std::string_view digits_at(std::string_view text, std::size_t& at) {
  const std::size_t start = at;
  while (at < text.size() && is_digit(text[at])) ++at;
  return text.substr(start, at - start);
}

}  // namespace

WholeNumberText read_whole_number(std::string_view text) {
  using Kind = WholeNumberText::Kind;
  std::size_t at = 0;
  const bool negative = at < text.size() && text[at] == '-';
  if (at < text.size() && (text[at] == '-' || text[at] == '+')) ++at;
  const std::string_view whole_part = digits_at(text, at);
  if (whole_part.empty()) return {Kind::not_a_number};
  std::string_view fraction;
  if (at < text.size() && text[at] == '.') fraction = digits_at(text, ++at);
  long exponent = 0;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    ++at;
    const bool exponent_negative = at < text.size() && text[at] == '-';
    if (at < text.size() && (text[at] == '-' || text[at] == '+')) ++at;
    const std::string_view exponent_digits = digits_at(text, at);
    if (exponent_digits.empty()) return {Kind::not_a_number};
    for (char c : exponent_digits)
      exponent = std::min(exponent * 10 + (c - '0'), 100'000L);  // capped: huge is huge
    if (exponent_negative) exponent = -exponent;
  }
  if (at != text.size()) return {Kind::not_a_number};
  if (whole_part.size() > 1 && whole_part[0] == '0') return {Kind::leading_zero};

  // The number is D × 10^scale, with D the digits of both parts and scale the exponent less the
  // fraction's length. It is whole when the digits the scale cuts off are zeros.
  std::string digits = std::string(whole_part) + std::string(fraction);
  long scale = exponent - long(fraction.size());
  digits.erase(0, digits.find_first_not_of('0'));  // "" when it is zero
  if (digits.empty()) return {Kind::whole, 0};
  while (scale < 0 && digits.back() == '0') digits.pop_back(), ++scale;
  if (scale < 0) return {Kind::not_whole};
  if (long(digits.size()) + scale > 19) return {Kind::too_large};
  digits.append(std::size_t(scale), '0');
  unsigned long long magnitude = 0;
  for (char c : digits) {
    if (magnitude > (ULLONG_MAX - 9) / 10) return {Kind::too_large};
    magnitude = magnitude * 10 + unsigned(c - '0');
  }
  const unsigned long long limit = negative ? static_cast<unsigned long long>(LONG_MAX) + 1 : LONG_MAX;
  if (magnitude > limit) return {Kind::too_large};
  const long value = negative ? (magnitude == limit ? LONG_MIN : -static_cast<long>(magnitude))
                              : static_cast<long>(magnitude);
  return {Kind::whole, value};
}

}  // namespace kit
