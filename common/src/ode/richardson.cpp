#include <kit/ode/richardson.hpp>

#include <cmath>

namespace kit {

Convergence richardson(double coarse, double middle, double fine) {
  Convergence c;
  const double d1 = middle - coarse, d2 = fine - middle;
  c.converges = d2 != 0 && d1 / d2 > 1;  // monotone and shrinking; an oscillation is not taken
  if (!c.converges) return c;
  const double ratio = d1 / d2;  // 2^p when the error falls like N^−p
  c.order = std::log2(std::abs(ratio));
  c.limit = fine + d2 / (ratio - 1);
  c.remaining = std::abs(fine - c.limit) / std::abs(c.limit);
  return c;
}

}  // namespace kit
