#pragma once
// The one exception for bad input files: its message names the file and, where one is
// to blame, the dotted field path: "LIB/cases/x.json: field result.eta_re_sem: must be a
// non-negative number". It derives from std::invalid_argument, like the other checks of
// what a user passed in (bad input, not a failure of the machine).
#include <stdexcept>
#include <string>

namespace rbcal::formats {

class FormatError : public std::invalid_argument {
 public:
  // "SOURCE: WHAT", for errors of the whole file (cannot open, not JSON).
  FormatError(const std::string& source, const std::string& what) : std::invalid_argument(source + ": " + what) {}
  // "SOURCE: field FIELD: WHAT".
  FormatError(const std::string& source, const std::string& field, const std::string& what)
      : std::invalid_argument(source + ": field " + field + ": " + what) {}
};

}  // namespace rbcal::formats
