#include "work_precision_report.hpp"

#include <optional>
#include <string>

namespace kit {

void report_work_precision(Report& report, std::string_view section, const std::vector<WorkCurve>& curves) {
  auto table = report.table(section, {{"method", "method"},
                                      {"tolerance", "tolerance", "{:.0e}"},
                                      {"RHS evals", "evaluations"},
                                      {"accepted", "accepted"},
                                      {"rejected", "rejected"},
                                      {"max |y(T) - ref|", "error", "{:.2e}"},
                                      {"time [s]", "seconds", "{:.2e}"},
                                      {"", "finished"}});

  long unfinished = 0;
  for (const WorkCurve& c : curves) {
    for (const WorkPoint& w : c.points) {
      table.append(c.label, {c.label, w.tolerance, w.rhs_evals, optional_value(w.accepted),
                             optional_value(w.rejected), w.error, w.seconds, w.finished});
      if (!w.finished) ++unfinished;
    }
  }
  table.print();
  if (unfinished > 0)
    report.say(
        std::string(section) + "_notes",
        "{unfinished} runs stopped before T (step budget or step too small): their error is not an error "
        "at T (\"finished\": false in the JSON).\n",
        {{"unfinished", unfinished}});
}

}  // namespace kit
