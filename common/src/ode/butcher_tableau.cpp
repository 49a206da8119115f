#include <kit/ode/butcher_tableau.hpp>

#include <cmath>
#include <functional>

#include <kit/ode/dopri5_coefficients.hpp>

namespace kit {
namespace {

constexpr long double q(long long numerator, long long denominator) {
  return static_cast<long double>(numerator) / static_cast<long double>(denominator);
}

ButcherTableau make_cash_karp(long double a63) {
  ButcherTableau t;
  t.c = {0, q(1, 5), q(3, 10), q(3, 5), 1, q(7, 8)};
  t.a = {{0, 0, 0, 0, 0, 0},
         {q(1, 5), 0, 0, 0, 0, 0},
         {q(3, 40), q(9, 40), 0, 0, 0, 0},
         {q(3, 10), q(-9, 10), q(6, 5), 0, 0, 0},
         {q(-11, 54), q(5, 2), q(-70, 27), q(35, 27), 0, 0},
         {q(1631, 55296), q(175, 512), a63, q(44275, 110592), q(253, 4096), 0}};
  t.b = {q(37, 378), 0, q(250, 621), q(125, 594), 0, q(512, 1771)};
  t.b_hat = {q(2825, 27648), 0, q(18575, 48384), q(13525, 55296), q(277, 14336), q(1, 4)};
  t.order = 5;
  t.embedded_order = 4;
  return t;
}

}  // namespace

const ButcherTableau& cash_karp() {
  static const ButcherTableau t = [] {
    auto tableau = make_cash_karp(q(575, 13824));
    tableau.name = "Cash-Karp 5(4)";
    return tableau;
  }();
  return t;
}

const ButcherTableau& cash_karp_as_printed() {
  static const ButcherTableau t = [] {
    auto tableau = make_cash_karp(q(-575, 13824));
    tableau.name = "the lecture's tableau, as printed (-575/13824)";
    return tableau;
  }();
  return t;
}

const ButcherTableau& dormand_prince() {
  static const ButcherTableau t = [] {
    ButcherTableau d;
    d.name = "Dormand-Prince 5(4)";
    // From the one source of the DOPRI5 fractions, the same the production integrator rounds.
    namespace F = dopri5_fraction;
    const auto exact = [](F::Fraction x) { return x.to_long_double(); };
    for (int i = 0; i < 7; ++i) {
      d.c.push_back(exact(F::c[i]));
      d.a.emplace_back();
      for (int j = 0; j < 7; ++j) d.a.back().push_back(exact(F::a[i][j]));
      d.b.push_back(exact(F::b[i]));
      d.b_hat.push_back(exact(F::b_hat[i]));
    }
    d.order = 5;
    d.embedded_order = 4;
    d.fsal = true;
    return d;
  }();
  return t;
}

const ButcherTableau& bogacki_shampine() {
  static const ButcherTableau t = [] {
    ButcherTableau d;
    d.name = "Bogacki-Shampine 3(2)";
    d.c = {0, q(1, 2), q(3, 4), 1};
    d.a = {{0, 0, 0, 0}, {q(1, 2), 0, 0, 0}, {0, q(3, 4), 0, 0}, {q(2, 9), q(1, 3), q(4, 9), 0}};
    d.b = {q(2, 9), q(1, 3), q(4, 9), 0};
    d.b_hat = {q(7, 24), q(1, 4), q(1, 3), q(1, 8)};
    d.order = 3;
    d.embedded_order = 2;
    d.fsal = true;
    return d;
  }();
  return t;
}

long double row_sum_defect(const ButcherTableau& t) {
  long double worst = 0;
  for (int i = 0; i < t.stages(); ++i) {
    long double sum = 0;
    for (long double aij : t.a[static_cast<std::size_t>(i)]) sum += aij;
    worst = std::max(worst, std::fabs(sum - t.c[static_cast<std::size_t>(i)]));
  }
  return worst;
}

int satisfied_order(const ButcherTableau& t, const std::vector<long double>& b, Nodes nodes,
                    long double tolerance) {
  const std::size_t s = static_cast<std::size_t>(t.stages());
  using Vec = std::vector<long double>;
  Vec c = t.c;
  if (nodes == Nodes::row_sums) {
    c.assign(s, 0);
    for (std::size_t i = 0; i < s; ++i)
      for (long double aij : t.a[i]) c[i] += aij;
  }
  const auto times_a = [&](const Vec& v) {  // (A v)_i
    Vec out(s, 0);
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) out[i] += t.a[i][j] * v[j];
    return out;
  };
  const auto times = [&](const Vec& u, const Vec& v) {  // elementwise
    Vec out(s);
    for (std::size_t i = 0; i < s; ++i) out[i] = u[i] * v[i];
    return out;
  };
  const auto dot_b = [&](const Vec& v) {
    long double sum = 0;
    for (std::size_t i = 0; i < s; ++i) sum += b[i] * v[i];
    return sum;
  };
  const Vec one(s, 1), c2 = times(c, c), c3 = times(c2, c), c4 = times(c3, c);
  const Vec ac = times_a(c), ac2 = times_a(c2), ac3 = times_a(c3), aac = times_a(ac), aac2 = times_a(ac2);
  // The order conditions Σ b_i Φ_i(τ) = 1/γ(τ), one per rooted tree τ with up to 5 nodes.
  const std::vector<std::vector<std::pair<Vec, long double>>> conditions = {
      {{one, 1.0L}},
      {{c, 1.0L / 2}},
      {{c2, 1.0L / 3}, {ac, 1.0L / 6}},
      {{c3, 1.0L / 4}, {times(c, ac), 1.0L / 8}, {ac2, 1.0L / 12}, {aac, 1.0L / 24}},
      {{c4, 1.0L / 5},
       {times(c2, ac), 1.0L / 10},
       {times(c, ac2), 1.0L / 15},
       {times(c, aac), 1.0L / 30},
       {times(ac, ac), 1.0L / 20},
       {ac3, 1.0L / 20},
       {times_a(times(c, ac)), 1.0L / 40},
       {aac2, 1.0L / 60},
       {times_a(aac), 1.0L / 120}}};
  int order = 0;
  for (const auto& level : conditions) {
    for (const auto& [phi, target] : level)
      if (std::fabs(dot_b(phi) - target) > tolerance) return order;
    ++order;
  }
  return order;
}

}  // namespace kit
