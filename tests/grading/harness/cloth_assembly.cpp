// The student's program for cloth_assembly.hpp (ex 7.2): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "cloth_assembly.hpp"
#include "remote/fields/cloth_implicit_kernels.hpp"
#include "remote/student.hpp"

using namespace kit;

void register_entries(remote::Entries& e) {
  e.add("assemble_implicit_system",
        [](const Springs& springs, const NodeArray& x, const NodeArray& v, const NodeArray& f,
           const Eigen::VectorXd& masses, const std::vector<Mat3>& stiffness,
           const std::optional<double>& drag, double h, SparseMatrix& A, Eigen::VectorXd& b) {
          const ImplicitSystemInput in{springs, x, v, f, masses, stiffness, drag, h};
          assemble_implicit_system(in, A, b);
        });
}
