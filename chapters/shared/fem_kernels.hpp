#pragma once
// Chapter 9's wiring of the student's element into the kit (fem_element.hpp): ex 9.1 the
// deformation gradient and Green's strain, ex 9.2 the stress and the forces, ex 9.3 the
// stiffness. Not an exercise: an unwritten one throws NotImplemented when the kit calls it.
#include <kit/fem_element.hpp>

#include "fem_strain.hpp"
#include "fem_stvk_forces.hpp"
#include "fem_stvk_stiffness.hpp"

namespace kit {

inline FemKernels student_fem_kernels() {
  return {&deformation_gradient, &green_strain, &stvk_stress, &stvk_forces, &stvk_stiffness};
}

}  // namespace kit
