#pragma once
// Allowed ranges of real-valued flags, and how a usage message states them.
#include <limits>
#include <string>

namespace kit {

/// An interval of allowed real values. NaN and ±Inf are never allowed.
struct RealRange {
  double lo = -std::numeric_limits<double>::max();
  double hi = std::numeric_limits<double>::max();
  bool lo_open = false;
  bool hi_open = false;
  bool nonzero = false;  ///< additionally exclude 0

  bool contains(double value) const;
  /// "a finite number in (0, 10]", "any finite number", "a finite non-zero number".
  std::string describe() const;
};
RealRange any_finite();
RealRange nonzero_finite();
RealRange positive(double hi = std::numeric_limits<double>::max());  ///< (0, hi]
RealRange between(double lo, double hi);                             ///< [lo, hi]

}  // namespace kit
