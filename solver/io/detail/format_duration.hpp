#pragma once
// Wall-clock durations for progress lines: "12.3s", "4m05s", "2h07m".
#include <string>

namespace rbcal::solver {

std::string format_duration(double seconds);

}  // namespace rbcal::solver
