#include <climits>

#include <kit_catch.hpp>

#include <kit/base/whole_number.hpp>

using Kind = kit::WholeNumberText::Kind;

namespace {
long whole(const char* text) {
  const auto read = kit::read_whole_number(text);
  INFO(text);
  REQUIRE(read.kind == Kind::whole);
  return read.value;
}
Kind kind(const char* text) { return kit::read_whole_number(text).kind; }
}  // namespace

TEST_CASE("a whole number is read exactly from its decimal text, in any notation a scientist writes") {
  CHECK(whole("0") == 0);
  CHECK(whole("-0") == 0);
  CHECK(whole("+17") == 17);
  CHECK(whole("1e9") == 1'000'000'000);
  CHECK(whole("2.5e3") == 2500);
  CHECK(whole("1000e-3") == 1);
  CHECK(whole("1.E2") == 100);
  CHECK(whole("0.5e1") == 5);
  CHECK(whole("1e16") == 10'000'000'000'000'000);  // beyond 2^53: exact, no double in between
  CHECK(whole("9223372036854775807") == LONG_MAX);
  CHECK(whole("-9223372036854775808") == LONG_MIN);
  CHECK(whole("0e999999999999") == 0);
}

TEST_CASE("fractions, other notations and numbers beyond a long are told apart") {
  CHECK(kind("2.5") == Kind::not_whole);
  CHECK(kind("2.0000000000000001") == Kind::not_whole);  // a double would round it to 2
  CHECK(kind("1e-400") == Kind::not_whole);              // a double would underflow it to 0
  CHECK(kind("15e-1") == Kind::not_whole);
  CHECK(kind("9223372036854775808") == Kind::too_large);
  CHECK(kind("1e19") == Kind::too_large);
  CHECK(kind("1e999999999999") == Kind::too_large);
  CHECK(kind("010") == Kind::leading_zero);
  for (const char* text :
       {"", "-", "e5", ".5", "1e", "1e+", "0x10", " 5", "5 ", "inf", "nan", "1,000", "12abc", "1..2"}) {
    INFO("'" << text << "'");
    CHECK(kind(text) == Kind::not_a_number);
  }
}
