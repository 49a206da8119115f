#pragma once
// The judge's cloth_assembly.hpp (ex 7.2): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/cloth/cloth_implicit_kernels.hpp>

#include "remote/fields/cloth_implicit_kernels.hpp"
#include "remote/judge.hpp"

namespace kit {
/// The input holds references: its members travel one by one.
inline void assemble_implicit_system(const ImplicitSystemInput& in, SparseMatrix& A, Eigen::VectorXd& b) {
  remote::call<void>("assemble_implicit_system", in.springs, in.x, in.v, in.f, in.masses, in.stiffness,
                     in.drag, in.h, remote::inout(A), remote::inout(b));
}
}  // namespace kit
