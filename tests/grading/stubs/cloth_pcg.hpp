#pragma once
// The judge's cloth_pcg.hpp (ex 7.3): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <vector>

#include <kit/cloth/cloth_implicit_kernels.hpp>

#include "remote/fields/cloth_implicit_kernels.hpp"
#include "remote/judge.hpp"

namespace kit {
inline PcgResult filtered_pcg(const SparseMatrix& A, const Eigen::VectorXd& b,
                              const std::vector<Mat3>& filters, double tolerance, int max_iterations) {
  return remote::call<PcgResult>("filtered_pcg", A, b, filters, tolerance, max_iterations);
}
}  // namespace kit
