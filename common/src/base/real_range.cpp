#include <kit/base/real_range.hpp>

#include <cmath>

#include <fmt/format.h>

namespace kit {

bool RealRange::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (nonzero && v == 0.0) return false;
  if (lo_open ? !(v > lo) : !(v >= lo)) return false;
  if (hi_open ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string RealRange::describe() const {
  constexpr double big = std::numeric_limits<double>::max();
  const bool has_lo = lo > -big, has_hi = hi < big;
  std::string what = nonzero ? "a finite non-zero number" : "a finite number";
  if (!has_lo && !has_hi) return nonzero ? what : "any finite number";
  if (has_lo && !has_hi) return fmt::format("{} {} {}", what, lo_open ? ">" : ">=", lo);
  if (!has_lo && has_hi) return fmt::format("{} {} {}", what, hi_open ? "<" : "<=", hi);
  return fmt::format("{} in {}{}, {}{}", what, lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]");
}

RealRange any_finite() { return {}; }
RealRange nonzero_finite() {
  RealRange r;
  r.nonzero = true;
  return r;
}
RealRange positive(double hi) {
  RealRange r;
  r.lo = 0.0;
  r.lo_open = true;
  r.hi = hi;
  return r;
}
RealRange between(double lo, double hi) {
  RealRange r;
  r.lo = lo;
  r.hi = hi;
  return r;
}

}  // namespace kit
