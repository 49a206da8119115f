#pragma once
// A number as a README prints it: "2.37e-3", "12.48", "1.002". The test holds the README's own
// text, and a value matches it when it rounds to it, so the check is exactly as precise as the
// README: half a unit in the last digit printed, no more and no less. `slack` widens it by a
// stated amount where the README names one (a bisection's width, say).
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <kit_catch.hpp>

namespace kit::test {

/// Half a unit in the last printed digit of `text` (a decimal, optionally with an exponent).
inline double half_unit(const std::string& text) {
  const std::size_t e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::atoi(text.c_str() + e + 1);
  const std::size_t point = mantissa.find('.');
  const int decimals = point == std::string::npos ? 0 : int(mantissa.size() - point - 1);
  return 0.5 * std::pow(10.0, exponent - decimals);
}

/// CHECK(x == printed("12.48")): x rounds to 12.48, |x − 12.48| ≤ 0.005 (+ slack). Approx's own
/// relative epsilon (1.2e-5 by default) is set to round-off, so that it adds nothing.
/// A text that is not a number whole ("", "12%") is a mistake in the test: it throws.
inline Catch::Approx printed(const std::string& text, double slack = 0) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0') throw std::invalid_argument("printed(\"" + text + "\"): not a number");
  return Catch::Approx(value).margin(half_unit(text) + slack).epsilon(1e-12);
}

}  // namespace kit::test
