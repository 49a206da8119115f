// The student's program for explicit_euler.hpp (ex 1.1, 1.2): its entry points call the student's functions
// and return what they return (remote/student.hpp). It checks nothing.
#include "explicit_euler.hpp"
#include "remote/fields/affine_system.hpp"
#include "remote/student.hpp"

using namespace kit;
using namespace kit::remote;

namespace {
template <int N>
void add_affine(Entries& e) {
  add_stepper<ExplicitEulerAffine<N>, Vec<N>, AffineSystem<N>, double>(
      e, "ExplicitEulerAffine/" + key<Vec<N>>());
}
}  // namespace

void register_entries(Entries& e) {
  add_one_step<Vec<1>, Vec<2>, Vec<3, float>>(
      e, "explicit_euler_step",
      [](const auto& f, auto t, const auto& u, auto dt) { return explicit_euler_step(f, t, u, dt); });
  add_affine<2>(e), add_affine<3>(e);
}
