#pragma once
// The judge's implicit_euler.hpp (ex 1.3): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <string>

#include <kit/affine_system.hpp>

#include "remote/fields/affine_system.hpp"
#include "remote/judge.hpp"

namespace kit {

template <int N, class Scalar = double>
class ImplicitEulerAffine {
 public:
  ImplicitEulerAffine(const AffineSystem<N, Scalar>& system, Scalar dt) : id_(remote::call<long>(entry("new"), system, dt)) {}
  Vec<N, Scalar> step(const Vec<N, Scalar>& u) const { return remote::call<Vec<N, Scalar>>(entry("step"), id_, u); }

 private:
  static std::string entry(const char* what) { return "ImplicitEulerAffine/" + remote::key<Vec<N, Scalar>>() + "/" + what; }
  long id_;
};

}  // namespace kit
