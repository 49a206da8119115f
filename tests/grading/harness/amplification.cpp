// The student's program for amplification.hpp (ex 2.4): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "amplification.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add("amplification_factor",
        [](kit::Scheme scheme, std::complex<double> z) { return kit::amplification_factor(scheme, z); });
}
