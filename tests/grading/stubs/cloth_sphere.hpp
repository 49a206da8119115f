#pragma once
// The judge's cloth_sphere.hpp (ex 6.4): the exercise's names and signatures, each answered by the
// student's program (remote/judge.hpp). No student code is compiled here.
#include <kit/cloth/cloth.hpp>
#include <kit/cloth/cloth_scene.hpp>

#include "remote/fields/cloth_scene.hpp"
#include "remote/judge.hpp"

namespace kit {
inline long collide_sphere(NodeArray& x, NodeArray& v, const SphereCollider& sphere) {
  return remote::call<long>("collide_sphere", remote::inout(x), remote::inout(v), sphere);
}
}  // namespace kit
