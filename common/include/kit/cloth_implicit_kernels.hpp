#pragma once
// The path of <kit/cloth/cloth_implicit_kernels.hpp> before the library took its layers (base/, app/, ode/,
// …): kept for one release, so that an exercise copy written before still compiles and grades
// (tests/grading/points.json allows both). New code includes <kit/cloth/cloth_implicit_kernels.hpp>.
#include <kit/cloth/cloth_implicit_kernels.hpp>
