#pragma once
// Reading a count from a command line the way a scientist writes it: "1000000", "1e6", "2.5e3",
// "1000e-3" are whole numbers; "2.5", "1e-400", "0x10" are not. Decided exactly from the decimal
// text, never from a rounded double: "2.0000000000000001" is not whole, and "1e16" is exactly
// 10^16.
#include <optional>
#include <string_view>

namespace kit {

/// What a piece of text says as a whole number.
struct WholeNumberText {
  enum class Kind {
    whole,         ///< `value` holds it
    not_a_number,  ///< not [+-]digits[.digits][(e|E)[+-]digits], exactly (no spaces, no hex)
    not_whole,     ///< a number with a fractional part
    too_large,     ///< whole, but beyond a long
    leading_zero,  ///< "010": some tools read it as octal (8), others as 10; refused as ambiguous
  };
  Kind kind = Kind::not_a_number;
  long value = 0;
};

WholeNumberText read_whole_number(std::string_view text);

}  // namespace kit
