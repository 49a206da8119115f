#include <sstream>

#include <kit_catch.hpp>

#include <kit/app/table.hpp>

TEST_CASE("a table right-aligns columns by characters, not bytes") {
  kit::Table table({"Δt [s]", "match"});
  table.add_row({"0.1", "✓"});
  table.add_row({"0.001", "✗"});
  std::ostringstream out;
  table.print(out);
  CHECK(out.str() == "Δt [s]  match\n-------------\n   0.1      ✓\n 0.001      ✗\n");
}

TEST_CASE("a row with the wrong number of cells is refused") {
  kit::Table table({"a", "b"});
  CHECK_THROWS(table.add_row({"1"}));
}

TEST_CASE("number formats") {
  CHECK(kit::sci(0.00123456, 3) == "1.23e-03");
  CHECK(kit::fixed(2.0 / 3.0, 4) == "0.6667");
}
