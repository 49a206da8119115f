// The student's program for implicit_euler.hpp (ex 1.3): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "implicit_euler.hpp"
#include "remote/fields/affine_system.hpp"
#include "remote/student.hpp"

using namespace kit;
using namespace kit::remote;

namespace {
template <int N>
void add_affine(Entries& e) {
  add_stepper<ImplicitEulerAffine<N>, Vec<N>, AffineSystem<N>, double>(
      e, "ImplicitEulerAffine/" + key<Vec<N>>());
}
}  // namespace

void register_entries(Entries& e) { add_affine<1>(e), add_affine<2>(e), add_affine<3>(e); }
