#pragma once
// Chapter 9's wiring of the student's exercises into the kit (fem_element.hpp, fem_body.hpp):
// ex 9.1 the deformation gradient and Green's strain, ex 9.2 the stress and the forces, ex 9.3
// the stiffness; and from earlier chapters the spring (ex 6.1), its stiffness block (ex 7.1) and
// the filtered PCG (ex 7.3), which the springs model and the implicit step call. Not an
// exercise: an unwritten one throws NotImplemented when the kit calls it.
#include <kit/fem/fem_body.hpp>

#include "cloth_jacobian.hpp"
#include "cloth_pcg.hpp"
#include "cloth_spring_force.hpp"
#include "fem_strain.hpp"
#include "fem_stvk_forces.hpp"
#include "fem_stvk_stiffness.hpp"

namespace kit {

inline FemKernels student_fem_kernels() {
  return {&deformation_gradient, &green_strain, &stvk_stress, &stvk_forces, &stvk_stiffness};
}

inline ContinuumKernels student_continuum_kernels() {
  return {student_fem_kernels(), &spring_force, &spring_stiffness_block, &filtered_pcg};
}

}  // namespace kit
