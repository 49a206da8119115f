// The student's program for fem_stvk_stiffness.hpp (ex 9.3): its entry points call the student's functions
// and return what they return (remote/student.hpp). It checks nothing.
#include "fem_stvk_stiffness.hpp"
#include "remote/fields/fem_element.hpp"
#include "remote/student.hpp"

using namespace kit;

void register_entries(remote::Entries& e) {
  e.add("stvk_stiffness",
        [](const Matrix32& F, const Matrix2& rest_inverse, double rest_volume, const Lame& lame) -> Matrix9 {
          return stvk_stiffness(F, rest_inverse, rest_volume, lame);
        });
}
