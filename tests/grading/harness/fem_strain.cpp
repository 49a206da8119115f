// The student's program for fem_strain.hpp (ex 9.1): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "fem_strain.hpp"
#include "remote/fields/fem_element.hpp"
#include "remote/student.hpp"

using namespace kit;

void register_entries(remote::Entries& e) {
  e.add("deformation_gradient",
        [](const Vec3& x0, const Vec3& x1, const Vec3& x2, const Matrix2& rest_inverse) -> Matrix32 {
          return deformation_gradient(x0, x1, x2, rest_inverse);
        });
  e.add("green_strain", [](const Matrix32& F) -> Matrix2 { return green_strain(F); });
}
