// The student's program for cloth_jacobian.hpp (ex 7.1): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "cloth_jacobian.hpp"
#include "remote/fields/cloth_implicit_kernels.hpp"
#include "remote/student.hpp"

using kit::Vec3;

void register_entries(kit::remote::Entries& e) {
  e.add("spring_stiffness_block",
        [](const Vec3& xa, const Vec3& xb, double rest, double stiffness, bool clamp) {
          return kit::spring_stiffness_block(xa, xb, rest, stiffness, clamp);
        });
}
