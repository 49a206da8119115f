#pragma once
// The judge's cloth_step.hpp (ex 6.3): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <cstdint>
#include <vector>

#include <kit/cloth/cloth.hpp>

#include "remote/fields/cloth.hpp"
#include "remote/judge.hpp"

namespace kit {
template <class Forces>
void symplectic_cloth_step(NodeArray& x, NodeArray& v, const Eigen::VectorXd& masses,
                           const std::vector<std::int32_t>& pins, const Forces& forces, NodeArray& f,
                           double dt) {
  remote::call<void>("symplectic_cloth_step", remote::inout(x), remote::inout(v), masses, pins,
                     remote::callback<void(const NodeArray&, const NodeArray&, NodeArray&)>(forces),
                     remote::inout(f), dt);
}
}  // namespace kit
