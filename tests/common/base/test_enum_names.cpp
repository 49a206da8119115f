// kit::EnumNames (enum_names.hpp): one table gives a value's names, a name's value and a flag's
// choices, in the table's order.
#include <string>
#include <vector>

#include <kit_catch.hpp>

#include <kit/base/enum_names.hpp>
#include <kit/cloth/cloth_scene.hpp>
#include <kit/problems/orbit_problem.hpp>
#include <kit/sprites/particle_update.hpp>

namespace {

enum class Colour { red, green, blue };
constexpr auto colour_names = kit::enum_names<Colour>({
    {Colour::red, "red", "Red"},
    {Colour::green, "green", "Green"},
    {Colour::blue, "blue", "Blue"},
});
constexpr auto shuffled = kit::enum_names<Colour>({
    {Colour::green, "green", "Green"},
    {Colour::red, "red", "Red"},
    {Colour::blue, "blue", "Blue"},
});
constexpr auto short_one =
    kit::enum_names<Colour>({{Colour::red, "red", "Red"}, {Colour::blue, "blue", "Blue"}});

}  // namespace

TEST_CASE("a name table prints, parses and lists its values, in its order") {
  static_assert(colour_names.in_order());
  CHECK(std::string(colour_names.flag(Colour::green)) == "green");
  CHECK(std::string(colour_names.display(Colour::blue)) == "Blue");
  CHECK(colour_names.parse("red") == Colour::red);
  CHECK(colour_names.parse("Red") == std::nullopt);  // flags are the flag names, not the display ones
  CHECK(colour_names.parse("") == std::nullopt);
  CHECK(colour_names.flags() == std::vector<std::string>{"red", "green", "blue"});
  CHECK(colour_names.all() == std::array{Colour::red, Colour::green, Colour::blue});
  for (const Colour c : colour_names.all()) CHECK(colour_names.parse(colour_names.flag(c)) == c);
}

TEST_CASE("a table whose rows are out of the enumeration's order, or short of a value, says so") {
  static_assert(!shuffled.in_order());
  static_assert(short_one.in_order() == false);
  CHECK_THROWS_AS(short_one.flag(Colour::blue), std::out_of_range);
}

TEST_CASE("the kit's tables keep the names its flags, scene files and summaries always used") {
  CHECK(kit::integrator_names.flags() ==
        std::vector<std::string>{"euler", "symplectic", "midpoint", "exact"});
  CHECK(std::string(kit::display_name(kit::ClothIntegrator::midpoint)) == "midpoint (RK2)");
  CHECK(kit::cloth_integrator_names.parse("symplectic-euler") == kit::ClothIntegrator::symplectic_euler);
  CHECK(std::string(kit::spring_kind_name(kit::SpringKind::bend)) == "bend");
  CHECK(kit::orbit_names.flags() == std::vector<std::string>{"arenstorf", "kepler"});
}
