// The student's program for sprite_over.hpp (ex 5.3): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "sprite_over.hpp"
#include "remote/fields/image.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add("composite_over",
        [](kit::Image& image, const kit::SpriteTile& tile) { kit::composite_over(image, tile); });
}
