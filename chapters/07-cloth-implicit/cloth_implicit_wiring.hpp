#pragma once
// Chapter 7's wiring of the student's exercises into the kit's implicit cloth: ex 7.1 the
// spring's stiffness block, ex 7.2 the assembly the kit checks its own against, ex 7.3 the
// filtered PCG of --solver pcg. Not an exercise.
#include <kit/cloth/cloth_implicit_kernels.hpp>

#include "cloth_assembly.hpp"
#include "cloth_jacobian.hpp"
#include "cloth_pcg.hpp"

namespace kit {

/// The student's kernels; each throws NotImplemented (naming its exercise) until it is written.
inline ImplicitKernels student_implicit_kernels() {
  return {&spring_stiffness_block, &assemble_implicit_system, &filtered_pcg};
}

}  // namespace kit
