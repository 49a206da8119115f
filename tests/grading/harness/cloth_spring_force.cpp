// The student's program for cloth_spring_force.hpp (ex 6.1): its entry points call the student's functions
// and return what they return (remote/student.hpp). It checks nothing.
#include "cloth_spring_force.hpp"
#include "remote/fields/cloth.hpp"
#include "remote/student.hpp"

using kit::Vec3;

void register_entries(kit::remote::Entries& e) {
  e.add("spring_force",
        [](const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double rest,
           const kit::SpringFamily& family) -> Vec3 {
          return kit::spring_force(xa, xb, va, vb, rest, family);
        });
}
