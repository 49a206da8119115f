#pragma once
// Chapter 8's wiring of the student's exercises into the kit's rotation integrators
// (rigid_stepper.hpp): ex 8.1 the explicit step on R, ex 8.2 the quaternion step, ex 8.3 ω from
// L, ex 8.4 the exponential map. Not an exercise: an unwritten one throws NotImplemented when
// an integrator calls it, and the chapter names it.
#include <kit/rigid/rigid_stepper.hpp>

#include "rigid_angular_velocity.hpp"
#include "rigid_exponential_map.hpp"
#include "rigid_quaternion_step.hpp"
#include "rigid_rotation_step.hpp"

namespace kit {

inline RigidKernels student_rigid_kernels() {
  return {&explicit_rotation_step, &quaternion_step, &angular_velocity, &exponential_map_step};
}

}  // namespace kit
