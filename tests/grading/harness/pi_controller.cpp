// The student's program for pi_controller.hpp (ex 4.3): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "pi_controller.hpp"
#include "remote/fields/pi_law.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add("pi_step_factor", [](const kit::PiController& c, double err) { return kit::pi_step_factor(c, err); });
}
