#pragma once
// x^p for a fixed exponent p, in about fifteen instructions and no call: what a step-size
// controller needs on the critical path of every step, where std::pow (a log and an exp,
// ~80 cycles of latency) would cost more than the step's arithmetic.
//
// Write x = 2^k · z with z in [1, 2). Then x^p = 2^(p·k) · z^p: the first factor comes from a
// table over k, the second from a quadratic through z^p at the ends and middle of one of 256
// slices of [1, 2). On a slice of width w = 1/256 the interpolation error is at most
// |p(p−1)(p−2)|·(w/2)³/(9√3) relative: 9.2e-11 for DOPRI5's p = −0.085, 2.5e-10 for
// |p| ≤ 0.2, 2.9e-9 for |p| ≤ 1 (tests/common/base/test_fast_power.cpp measures these).
// Outside [2^−128, 2^128) (and for x ≤ 0, Inf or NaN) it falls back to std::pow. The exponent
// must satisfy |p| ≤ 8, so that 2^(p·k) stays finite over the table.
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace kit {

class FastPower {
 public:
  /// Throws std::invalid_argument unless |p| ≤ 8.
  explicit FastPower(double p);

  double exponent() const { return p_; }

  /// x^p for x > 0.
  double operator()(double x) const { return scaled(x, 1.0); }

  /// scale · x^p. The scale meets the table's 2^(p·k) while the quadratic is still being
  /// evaluated, so it adds no latency.
  double scaled(double x, double scale) const {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const auto k = std::int64_t(bits >> 52) - 1023 + kExponents / 2;  // biased exponent, shifted
    if (std::uint64_t(k) >= std::uint64_t(kExponents)) return scale * std::pow(x, p_);
    const Slice& s = slices_[(bits >> 44) & (kSlices - 1)];
    const double z = std::bit_cast<double>((bits & kMantissa) | kOne);  // x / 2^k, in [1, 2)
    return (scale * powers_of_two_[std::size_t(k)]) * ((s.c0 + s.c1 * z) + s.c2 * (z * z));
  }

 private:
  static constexpr int kExponents = 256, kSlices = 256;
  static constexpr std::uint64_t kMantissa = 0x000F'FFFF'FFFF'FFFFull, kOne = 0x3FF0'0000'0000'0000ull;
  struct Slice {
    double c0, c1, c2;  ///< z^p ≈ c0 + c1·z + c2·z² on the slice
  };
  double p_;
  std::array<double, kExponents> powers_of_two_;  ///< 2^(p·k), k = −128 … 127
  std::array<Slice, kSlices> slices_;
};

/// The table for exponent p, built once per thread and exponent (~30 µs) and then shared.
const FastPower& fast_power(double p);

}  // namespace kit
