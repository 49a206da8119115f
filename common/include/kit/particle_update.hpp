#pragma once
// The path of <kit/sprites/particle_update.hpp> before the library took its layers (base/, app/, ode/, …):
// kept for one release, so that an exercise copy written before still compiles and grades
// (tests/grading/points.json allows both). New code includes <kit/sprites/particle_update.hpp>.
#include <kit/sprites/particle_update.hpp>
