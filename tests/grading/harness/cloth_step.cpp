// The student's program for cloth_step.hpp (ex 6.3): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "cloth_step.hpp"
#include "remote/fields/cloth.hpp"
#include "remote/student.hpp"

using kit::NodeArray;

void register_entries(kit::remote::Entries& e) {
  e.add("symplectic_cloth_step",
        [](NodeArray& x, NodeArray& v, const Eigen::VectorXd& masses, const std::vector<std::int32_t>& pins,
           kit::remote::Callback<void(const NodeArray&, const NodeArray&, NodeArray&)> forces, NodeArray& f,
           double dt) { kit::symplectic_cloth_step(x, v, masses, pins, forces, f, dt); });
}
