// The student's program for cloth_pcg.hpp (ex 7.3): its entry points call the student's functions and
// return what they return (remote/student.hpp). It checks nothing.
#include "cloth_pcg.hpp"
#include "remote/fields/cloth_implicit_kernels.hpp"
#include "remote/student.hpp"

void register_entries(kit::remote::Entries& e) {
  e.add("filtered_pcg", [](const kit::SparseMatrix& A, const Eigen::VectorXd& b,
                           const std::vector<kit::Mat3>& filters, double tolerance, int max_iterations) {
    return kit::filtered_pcg(A, b, filters, tolerance, max_iterations);
  });
}
