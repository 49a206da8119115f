// The student's program for rigid_angular_velocity.hpp (ex 8.3): its entry points call the student's
// functions and return what they return (remote/student.hpp). It checks nothing.
#include "rigid_angular_velocity.hpp"
#include "remote/student.hpp"

using kit::Mat3;
using kit::Vec3;

void register_entries(kit::remote::Entries& e) {
  e.add("angular_velocity", [](const Mat3& R, const Mat3& inverse, const Vec3& L) -> Vec3 {
    return kit::angular_velocity(R, inverse, L);
  });
}
