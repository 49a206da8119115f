#include <kit/base/fast_power.hpp>

#include <memory>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

namespace kit {

FastPower::FastPower(double p) : p_(p) {
  if (!(std::abs(p) <= 8.0))
    throw std::invalid_argument(fmt::format("FastPower: exponent p = {} is outside [-8, 8]", p));
  for (int k = 0; k < kExponents; ++k)
    powers_of_two_[std::size_t(k)] = std::exp2(p * double(k - kExponents / 2));
  for (int j = 0; j < kSlices; ++j) {
    // The quadratic through (a, a^p), (m, m^p), (b, b^p) in Newton form,
    //   a^p + d1·(z − a) + d2·(z − a)(z − m),
    // expanded to monomials so that evaluating it is two multiply-adds deep.
    const double a = 1.0 + double(j) / kSlices, b = 1.0 + double(j + 1) / kSlices, m = 0.5 * (a + b);
    const double fa = std::pow(a, p), fm = std::pow(m, p), fb = std::pow(b, p);
    const double d1 = (fm - fa) / (m - a), d2 = ((fb - fm) / (b - m) - d1) / (b - a);
    slices_[std::size_t(j)] = {fa - d1 * a + d2 * a * m, d1 - d2 * (a + m), d2};
  }
}

const FastPower& fast_power(double p) {
  // A handful of exponents per program (DOPRI5 uses two): a linear search beats a map.
  thread_local std::vector<std::unique_ptr<FastPower>> tables;
  for (const auto& table : tables)
    if (table->exponent() == p) return *table;
  return *tables.emplace_back(std::make_unique<FastPower>(p));
}

}  // namespace kit
