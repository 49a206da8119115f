// The student's program for step_doubling.hpp (ex 4.1): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "step_doubling.hpp"
#include "remote/fields/adaptive_run.hpp"
#include "remote/student.hpp"

namespace kit {
inline auto fields(StepDoubling& o) {
  return std::tie(o.e_min, o.e_max, o.dt0, o.dt_min, o.max_retries, o.max_steps, o.guarded);
}
}  // namespace kit

using namespace kit;
using namespace kit::remote;

void register_entries(Entries& e) {
  using V = Vec<1>;
  e.add("step_doubling/" + key<V>(),
        [](Callback<V(double, const V&, double)> step, double t0, const V& u, double t_end,
           const StepDoubling& options) { return step_doubling(step, t0, u, t_end, options); });
}
