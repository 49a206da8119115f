// The student's program for spring_system.hpp (ex 2.1): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "spring_system.hpp"
#include "remote/fields/affine_system.hpp"
#include "remote/fields/spring.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add("spring_system", [](const kit::Spring& s) { return kit::spring_system(s); });
}
