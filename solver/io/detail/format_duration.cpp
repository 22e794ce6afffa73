#include "solver/io/detail/format_duration.hpp"

#include <iomanip>
#include <sstream>

namespace rbcal::solver {

std::string format_duration(double s) {
  std::ostringstream o;
  if (s >= 3600) o << static_cast<int>(s / 3600) << "h" << std::setw(2) << std::setfill('0') << static_cast<int>(s / 60) % 60 << "m";
  else if (s >= 60) o << static_cast<int>(s / 60) << "m" << std::setw(2) << std::setfill('0') << static_cast<int>(s) % 60 << "s";
  else o << std::fixed << std::setprecision(1) << s << "s";
  return o.str();
}

}  // namespace rbcal::solver
