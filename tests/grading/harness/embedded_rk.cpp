// The student's program for embedded_rk.hpp (ex 4.2): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "embedded_rk.hpp"
#include <kit/base/state.hpp>
#include "remote/fields/embedded_rk.hpp"
#include "remote/student.hpp"

using namespace kit;
using namespace kit::remote;

namespace {
template <class State>
void add_step(Entries& e) {
  e.add("embedded_step/" + key<State>(),
        [](Callback<State(double, const State&)> f, const ButcherTableau& tableau, double t, const State& y,
           double h, const State& k1) { return embedded_step(f, tableau, t, y, h, k1); });
}
}  // namespace

void register_entries(Entries& e) { add_step<Vec<1>>(e), add_step<Vec<2>>(e), add_step<Vec<4>>(e); }
