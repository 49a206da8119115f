// The student's program for symplectic_euler.hpp (ex 2.3): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "symplectic_euler.hpp"
#include "remote/student.hpp"

using namespace kit;
using namespace kit::remote;

namespace {
template <int N>
void add_step(Entries& e) {
  using Half = Vec<N / 2>;
  e.add("symplectic_euler_step/" + key<Vec<N>>(),
        [](Callback<Half(double, const Half&, const Half&)> accel, double t, const Vec<N>& u,
           double dt) -> Vec<N> { return symplectic_euler_step(accel, t, u, dt); });
}
}  // namespace

void register_entries(Entries& e) {
  add_step<2>(e), add_step<4>(e);
  e.add("symplectic_euler_oscillator_orbit", [](const Vec2& u0, double h, long n) {
    if (n < 0 || n > 2'000'000) throw std::invalid_argument("orbit: n out of range");
    const auto oscillator = [](double, const Vec<1>& x, const Vec<1>&) { return Vec<1>(-x[0]); };
    std::vector<Vec2> orbit;
    orbit.reserve(std::size_t(n));
    Vec2 u = u0;
    for (long k = 0; k < n; ++k) orbit.push_back(u = symplectic_euler_step(oscillator, 0.0, u, h));
    return orbit;
  });
}
