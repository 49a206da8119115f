#include <kit/base/measure.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace kit {

LogLogFit fit_loglog(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size() || x.size() < 2)
    throw std::invalid_argument("fit_loglog needs two or more (x, y) pairs of equal count");
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] > 0) || !(y[i] > 0))
      throw std::invalid_argument("fit_loglog needs positive values (log of x and y)");
    const double lx = std::log10(x[i]), ly = std::log10(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  const double denominator = n * sxx - sx * sx;
  if (denominator == 0) throw std::invalid_argument("fit_loglog needs two distinct x values");
  LogLogFit fit;
  fit.slope = (n * sxy - sx * sy) / denominator;
  fit.intercept = (sy - fit.slope * sx) / n;
  return fit;
}

std::vector<long> geometric_counts(long lo, long hi, int per_decade) {
  if (lo < 1 || hi < lo || per_decade < 1)
    throw std::invalid_argument("geometric_counts needs 1 <= lo <= hi and per_decade >= 1");
  std::vector<long> counts;
  const double decades = std::log10(static_cast<double>(hi) / static_cast<double>(lo));
  const long points = static_cast<long>(std::ceil(decades * per_decade - 1e-9));
  for (long i = 0; i <= points; ++i) {
    const double fraction = points == 0 ? 0.0 : static_cast<double>(i) / static_cast<double>(points);
    const long n = std::lround(static_cast<double>(lo) * std::pow(10.0, fraction * decades));
    if (counts.empty() || n > counts.back()) counts.push_back(n);
  }
  return counts;
}

std::size_t argmin(std::span<const double> values) {
  std::size_t best = values.size();
  double best_value = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isfinite(values[i]) && (best == values.size() || values[i] < best_value)) {
      best = i;
      best_value = values[i];
    }
  }
  if (best == values.size()) throw std::invalid_argument("argmin of no finite value");
  return best;
}

double cost_to_reach(std::span<const double> cost, std::span<const double> error, double target) {
  std::vector<std::size_t> order(cost.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] < cost[b]; });
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    if (!(error[i] <= target)) continue;
    if (k == 0) return cost[i];  // already below target at the cheapest run
    const std::size_t j = order[k - 1];
    const double s = std::log(error[j] / target) / std::log(error[j] / error[i]);
    return std::exp(std::log(cost[j]) + s * std::log(cost[i] / cost[j]));
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double Sweep::order() const {
  std::vector<double> x, y;
  for (std::size_t i = 0; i < dt.size(); ++i)
    if (error[i] > 0 && dt[i] > 0) x.push_back(dt[i]), y.push_back(error[i]);
  return x.size() < 2 ? std::numeric_limits<double>::quiet_NaN() : fit_loglog(x, y).slope;
}

bool agrees(double measured, double predicted, double rel, double abs) {
  return std::abs(measured - predicted) <= rel * std::abs(predicted) + abs;
}

}  // namespace kit
