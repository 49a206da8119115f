#pragma once
// The judge's implicit_euler.hpp (ex 1.3): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <string>

#include <kit/problems/affine_system.hpp>

#include "remote/fields/affine_system.hpp"
#include "remote/judge.hpp"

namespace kit {

template <int N, class Scalar = double>
class ImplicitEulerAffine : public remote::RemoteStepper<Vec<N, Scalar>> {
 public:
  ImplicitEulerAffine(const AffineSystem<N, Scalar>& system, Scalar dt)
      : remote::RemoteStepper<Vec<N, Scalar>>("ImplicitEulerAffine/" + remote::key<Vec<N, Scalar>>(), system,
                                              dt) {}
};

}  // namespace kit
