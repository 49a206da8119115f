#include <kit_catch.hpp>

#include <kit/ode/butcher_tableau.hpp>

TEST_CASE("every shipped tableau has consistent row sums and its claimed orders (long double)") {
  for (const auto* t : {&kit::cash_karp(), &kit::dormand_prince(), &kit::bogacki_shampine()}) {
    INFO(t->name);
    CHECK(kit::row_sum_defect(*t) < 1e-18L);
    CHECK(kit::satisfied_order(*t, t->b) == t->order);
    CHECK(kit::satisfied_order(*t, t->b_hat) == t->embedded_order);
    CHECK(kit::satisfied_order(*t, t->b, kit::Nodes::row_sums) == t->order);
    for (std::size_t i = 0; i < t->a.size(); ++i)
      for (std::size_t j = i; j < t->a.size(); ++j) CHECK(t->a[i][j] == 0);  // explicit
  }
}

TEST_CASE("the lecture's tableau as printed (−575/13824) breaks row 6 and drops to order 2, or 1 on "
          "autonomous problems") {
  const auto& printed = kit::cash_karp_as_printed();
  long double row6 = 0;
  for (long double a : printed.a[5]) row6 += a;
  CHECK(row6 == Approx(5473.0 / 6912.0).epsilon(1e-15));  // not c6 = 7/8
  CHECK(kit::row_sum_defect(printed) == Approx(7.0 / 8.0 - 5473.0 / 6912.0).epsilon(1e-12));
  CHECK(kit::satisfied_order(printed, printed.b) == 2);  // ERRATA item 9: the third-order condition fails
  CHECK(kit::satisfied_order(printed, printed.b_hat) == 2);
  CHECK(kit::satisfied_order(printed, printed.b, kit::Nodes::row_sums) == 1);
}

TEST_CASE("Cash–Karp and Dormand–Prince are different pairs: their nodes differ (ERRATA item 8)") {
  CHECK(kit::cash_karp().c[3] == Approx(3.0 / 5.0));
  CHECK(kit::dormand_prince().c[3] == Approx(4.0 / 5.0));
  CHECK(kit::dormand_prince().c[4] == Approx(8.0 / 9.0));
  CHECK(kit::dormand_prince().fsal);
  CHECK_FALSE(kit::cash_karp().fsal);
}
