#pragma once
// The path of <kit/ode/butcher_tableau.hpp> before the library took its layers (base/, app/, ode/, …): kept
// for one release, so that an exercise copy written before still compiles and grades
// (tests/grading/points.json allows both). New code includes <kit/ode/butcher_tableau.hpp>.
#include <kit/ode/butcher_tableau.hpp>
