#include "surrogate/leave_one_out_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace rbcal::surrogate {

std::string format_leave_one_out(const LeaveOneOutReport& report, double warn_limit) {
  std::ostringstream o;
  char line[256];
  o << "leave-one-out (each case predicted from all the others):\n";
  std::snprintf(line, sizeof line, "  %-28s %10s %10s %10s %9s %8s\n", "case", "eta_re", "predicted", "sd", "rel.err",
                "z");
  o << line;
  for (const LeaveOneOutCase& c : report.cases) {
    std::snprintf(line, sizeof line, "  %-28s %10.5f %10.5f %10.5f %8.2f%% %8.2f\n", c.id.c_str(), c.eta_re,
                  c.eta_re_predicted, c.sd, 100.0 * c.relative_error, c.standardised_residual);
    o << line;
  }
  std::snprintf(line, sizeof line,
                "  RMS relative error %.3g %%, RMS standardised residual %.3g (about 1 if the variances are right), "
                "max |z| %.3g\n",
                100.0 * report.rms_relative_error, report.rms_standardised_residual,
                report.max_abs_standardised_residual);
  o << line;
  for (const LeaveOneOutCase& c : report.cases)
    if (std::abs(c.standardised_residual) > warn_limit) {
      std::snprintf(line, sizeof line,
                    "warning: case %s: standardised leave-one-out residual %.2f (|z| > %.3g): an outlier, an "
                    "underestimated SEM, or a feature the library does not resolve\n",
                    c.id.c_str(), c.standardised_residual, warn_limit);
      o << line;
    }
  return o.str();
}

}  // namespace rbcal::surrogate
