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
  static Objects<ImplicitEulerAffine<N>> objects;
  const std::string name = "ImplicitEulerAffine/" + key<Vec<N>>() + "/";
  e.add(name + "new", [](const AffineSystem<N>& s, double dt) {
    return objects.keep(std::make_unique<ImplicitEulerAffine<N>>(s, dt));
  });
  e.add(name + "step", [](long id, const Vec<N>& u) -> Vec<N> { return objects.at(id).step(u); });
}
}  // namespace

void register_entries(Entries& e) { add_affine<1>(e), add_affine<2>(e), add_affine<3>(e); }
