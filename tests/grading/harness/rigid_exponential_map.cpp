// The student's program for rigid_exponential_map.hpp (ex 8.4): its entry points call the student's functions
// and return what they return (remote/student.hpp). It checks nothing.
#include "rigid_exponential_map.hpp"
#include "remote/student.hpp"

using kit::Mat3;
using kit::Vec3;

void register_entries(kit::remote::Entries& e) {
  e.add_iterable("exponential_map_step", [](const Mat3& R, const Vec3& omega, double h) -> Mat3 {
    return kit::exponential_map_step(R, omega, h);
  });
}
