#pragma once
// Chapter 6's wiring of the student's exercises into the kit's cloth: ex 6.2 builds the springs,
// ex 6.3 steps symplectic Euler, ex 6.4 answers sphere contacts. Not an exercise.
#include <kit/cloth/cloth_system.hpp>

#include "cloth_sphere.hpp"
#include "cloth_springs.hpp"
#include "cloth_step.hpp"

namespace kit {

/// The student's kernels. Each throws NotImplemented (naming its exercise) when first called
/// until it is written, so a section that needs it says what it waits for.
inline ClothKernels student_cloth_kernels() {
  return {&build_springs, &symplectic_cloth_step<ClothForces>, &collide_sphere};
}

}  // namespace kit
