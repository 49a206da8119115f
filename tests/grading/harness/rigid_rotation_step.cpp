// The student's program for rigid_rotation_step.hpp (ex 8.1): its entry points call the student's functions
// and return what they return (remote/student.hpp). It checks nothing.
#include "rigid_rotation_step.hpp"
#include "remote/student.hpp"

using kit::Mat3;
using kit::Vec3;

void register_entries(kit::remote::Entries& e) {
  e.add("skew", [](const Vec3& w) -> Mat3 { return kit::skew(w); });
  e.add_iterable("explicit_rotation_step", [](const Mat3& R, const Vec3& omega, double h) -> Mat3 {
    return kit::explicit_rotation_step(R, omega, h);
  });
}
