// The student's program for rigid_quaternion_step.hpp (ex 8.2): its entry points call the student's functions
// and return what they return (remote/student.hpp). It checks nothing.
#include "rigid_quaternion_step.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add_iterable("quaternion_step", [](const kit::Quat& q, const kit::Vec3& omega, double h) -> kit::Quat {
    return kit::quaternion_step(q, omega, h);
  });
}
