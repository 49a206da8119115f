#pragma once
// The Dormand–Prince 5(4) coefficients as exact fractions, the one source of them in the kit
// (Hairer, Nørsett & Wanner, Solving ODEs I, table II.5.2; dense output from dopri5.f).
// kit::dormand_prince() turns them into a long double tableau for the order-condition checks;
// kit::dopri5 rounds each fraction once to double. The error weights e_i = b_i − b̂_i are
// formed here in exact integer arithmetic, so the two can never disagree.
#include <numeric>

namespace kit::dopri5_fraction {

/// p/q with q > 0, reduced.
struct Fraction {
  long long p = 0, q = 1;
  constexpr double to_double() const { return double(p) / double(q); }  // one rounding
  constexpr long double to_long_double() const {
    return static_cast<long double>(p) / static_cast<long double>(q);
  }
};
constexpr Fraction reduce(long long p, long long q) {
  const long long g = std::gcd(p < 0 ? -p : p, q);
  return {p / g, q / g};
}
constexpr Fraction operator-(Fraction x, Fraction y) { return reduce(x.p * y.q - y.p * x.q, x.q * y.q); }
constexpr bool operator==(Fraction x, Fraction y) { return x.p == y.p && x.q == y.q; }

// Nodes c_i.
inline constexpr Fraction c[7] = {{0, 1}, {1, 5}, {3, 10}, {4, 5}, {8, 9}, {1, 1}, {1, 1}};
// Stage coefficients a_ij, row i, strictly lower triangular.
inline constexpr Fraction a[7][7] = {
    {},
    {{1, 5}},
    {{3, 40}, {9, 40}},
    {{44, 45}, {-56, 15}, {32, 9}},
    {{19372, 6561}, {-25360, 2187}, {64448, 6561}, {-212, 729}},
    {{9017, 3168}, {-355, 33}, {46732, 5247}, {49, 176}, {-5103, 18656}},
    {{35, 384}, {0, 1}, {500, 1113}, {125, 192}, {-2187, 6784}, {11, 84}},
};
// Weights of the propagated fifth-order solution: row 7 of a (FSAL), and b_7 = 0.
inline constexpr Fraction b[7] = {{35, 384},     {0, 1},   {500, 1113}, {125, 192},
                                  {-2187, 6784}, {11, 84}, {0, 1}};
// Weights of the embedded fourth-order solution.
inline constexpr Fraction b_hat[7] = {{5179, 57600},    {0, 1},      {7571, 16695}, {393, 640},
                                      {-92097, 339200}, {187, 2100}, {1, 40}};
// Error weights e_i = b_i − b̂_i (e_1 = 71/57600, …, e_7 = −1/40).
constexpr Fraction e(int i) { return b[i] - b_hat[i]; }
// Shampine's dense-output weights, as in dopri5.f.
inline constexpr Fraction d[7] = {{-12715105075LL, 11282082432LL},  {0, 1},
                                  {87487479700LL, 32700410799LL},   {-10690763975LL, 1880347072LL},
                                  {701980252875LL, 199316789632LL}, {-1453857185LL, 822651844LL},
                                  {69997945LL, 29380423LL}};

static_assert(e(0) == Fraction{71, 57600} && e(6) == Fraction{-1, 40}, "e = b - b_hat, HNW table II.5.2");

}  // namespace kit::dopri5_fraction
