#pragma once
// Explicit embedded Runge–Kutta pairs as data (Butcher tableaus), and the checks that prove
// them: row sums c_i = Σ_j a_ij, and the order conditions up to order 5, evaluated in
// long double from exact integer fractions.
#include <string>
#include <vector>

namespace kit {

/// An explicit embedded pair: y_{n+1} = y_n + h Σ b_i k_i (order `order`), and the embedded
/// solution with weights b̂ (order `embedded_order`) that estimates the error h Σ (b_i − b̂_i) k_i.
struct ButcherTableau {
  std::string name;
  std::vector<long double> c;               ///< nodes, size s
  std::vector<std::vector<long double>> a;  ///< s×s, strictly lower triangular
  std::vector<long double> b;               ///< weights of the propagated solution
  std::vector<long double> b_hat;           ///< weights of the embedded solution
  int order = 0;                            ///< claimed order of b
  int embedded_order = 0;                   ///< claimed order of b̂
  /// First same as last: the last stage is f(t + h, y_{n+1}) and serves as the next k_1, so a
  /// step costs s − 1 new evaluations.
  bool fsal = false;

  int stages() const { return static_cast<int>(c.size()); }
};

/// Cash & Karp 5(4), ACM TOMS 16 (1990): the tableau the lecture labels "Dormand-Prince
/// (ode45)", with c6 = 7/8 and the corrected +575/13824 in stage 6 (ERRATA items 8–9). It is
/// GSL's rkck: the 5th-order solution is propagated.
const ButcherTableau& cash_karp();
/// The same tableau as the lecture prints it, with −575/13824: row 6 then sums to 5473/6912,
/// not c6 = 7/8, and the pair drops to order 2. Kept to show it failing.
const ButcherTableau& cash_karp_as_printed();
/// Dormand & Prince 5(4), Hairer–Nørsett–Wanner table II.5.2, FSAL (DOPRI5, ode45, RK45).
const ButcherTableau& dormand_prince();
/// Bogacki & Shampine 3(2), FSAL (ode23).
const ButcherTableau& bogacki_shampine();

/// max_i |c_i − Σ_j a_ij|: 0 for a consistent tableau.
long double row_sum_defect(const ButcherTableau& tableau);

/// Which nodes the order conditions use.
enum class Nodes {
  printed,   ///< the tableau's c: what a non-autonomous problem sees through t + c_i h
  row_sums,  ///< c_i = Σ_j a_ij: what an autonomous problem sees, since only A shapes the stages
};

/// The highest order p ≤ 5 for which every order condition holds (to `tolerance`) for these
/// weights. For a consistent tableau both choices of nodes agree; the lecture's misprint shows
/// the difference (order 2 with its printed c, order 1 on autonomous problems).
int satisfied_order(const ButcherTableau& tableau, const std::vector<long double>& weights,
                    Nodes nodes = Nodes::printed, long double tolerance = 1e-15L);

}  // namespace kit
