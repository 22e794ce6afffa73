#pragma once
// Where and when a result was made, for the provenance block of output files.
#include <string>

namespace rbcal::solver {

std::string host_name();
std::string utc_now();  // ISO 8601, e.g. 2026-11-21T22:10:47Z

}  // namespace rbcal::solver
