// The student's program for cloth_springs.hpp (ex 6.2): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "cloth_springs.hpp"
#include "remote/fields/cloth.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add("build_springs", [](const kit::ClothGrid& grid, const kit::SpringLayout& layout) {
    return kit::build_springs(grid, layout);
  });
}
