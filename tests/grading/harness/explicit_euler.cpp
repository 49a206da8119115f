// The student's program for explicit_euler.hpp (ex 1.1, 1.2): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "explicit_euler.hpp"
#include "remote/fields/affine_system.hpp"
#include "remote/student.hpp"

using namespace kit;
using namespace kit::remote;

namespace {
template <class State>
void add_step(Entries& e) {
  using S = typename State::Scalar;
  e.add("explicit_euler_step/" + key<State>(),
        [](Callback<State(S, const State&)> f, S t, const State& u, S dt) -> State { return explicit_euler_step(f, t, u, dt); });
}
template <int N>
void add_affine(Entries& e) {
  static Objects<ExplicitEulerAffine<N>> objects;
  const std::string name = "ExplicitEulerAffine/" + key<Vec<N>>() + "/";
  e.add(name + "new", [](const AffineSystem<N>& s, double dt) {
    return objects.keep(std::make_unique<ExplicitEulerAffine<N>>(s, dt));
  });
  e.add(name + "step", [](long id, const Vec<N>& u) -> Vec<N> { return objects.at(id).step(u); });
}
}  // namespace

void register_entries(Entries& e) {
  add_step<Vec<1>>(e), add_step<Vec<2>>(e), add_step<Vec<3, float>>(e);
  add_affine<2>(e), add_affine<3>(e);
}
