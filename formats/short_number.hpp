#pragma once
// A number as the project's files and messages print it: six significant digits (or
// `digits`), no trailing zeros ("0.21", "1e-06"), as printf's %g. Case ids
// (phi0.21_Ca0.1_lambda5) and field errors use it.
#include <sstream>
#include <string>

namespace rbcal::formats {

inline std::string short_number(double v, int digits = 6) {
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

}  // namespace rbcal::formats
