// The student's program for fem_stvk_forces.hpp (ex 9.2): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "fem_stvk_forces.hpp"
#include "remote/fields/fem_element.hpp"
#include "remote/student.hpp"

using namespace kit;

void register_entries(remote::Entries& e) {
  e.add("stvk_stress", [](const Matrix2& E, const Lame& lame) -> Matrix2 { return stvk_stress(E, lame); });
  e.add("stvk_forces",
        [](const Matrix32& F, const Matrix2& rest_inverse, double rest_volume,
           const Lame& lame) -> ElementForces { return stvk_forces(F, rest_inverse, rest_volume, lame); });
}
