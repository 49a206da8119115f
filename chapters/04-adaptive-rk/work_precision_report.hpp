#pragma once
// A work-precision measurement (work_precision.hpp) in the text and the JSON, from one call:
// one printed row per point, stored as summary[section][method label][i] = {method, tolerance,
// evaluations, accepted, rejected, error, seconds, finished}; counts a method does not report
// print "-" and are null. Runs that stopped before T are counted in a closing sentence.
#include <ostream>
#include <string_view>
#include <vector>

#include <kit/app/report.hpp>
#include <kit/ode/work_precision.hpp>

namespace kit {

void report_work_precision(Report& report, std::string_view section, const std::vector<WorkCurve>& curves);

}  // namespace kit
