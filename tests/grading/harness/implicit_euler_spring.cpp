// The student's program for implicit_euler_spring.hpp (ex 2.2): its entry points call the student's functions
// and return what they return (remote/student.hpp). It checks nothing.
#include "implicit_euler_spring.hpp"
#include "remote/fields/spring.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add("implicit_euler_spring_step", [](const kit::Spring& s, const kit::Vec2& u, double dt) -> kit::Vec2 {
    return kit::implicit_euler_spring_step(s, u, dt);
  });
}
