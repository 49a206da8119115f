// The student's program for cloth_spring_force.hpp (ex 6.1): its entry points call the student's functions
// and return what they return (remote/student.hpp). It checks nothing.
#include "cloth_spring_force.hpp"
#include "remote/fields/cloth.hpp"
#include "remote/student.hpp"

using kit::Vector3;

void register_entries(kit::remote::Entries& e) {
  e.add("spring_force",
        [](const Vector3& xa, const Vector3& xb, const Vector3& va, const Vector3& vb, double rest,
           const kit::SpringFamily& family) -> Vector3 {
          return kit::spring_force(xa, xb, va, vb, rest, family);
        });
}
