#pragma once
// Where and when a file was made: the one provenance block of every file rbcal writes
// (case results, surrogates, calibration reports, benchmarks).
//   {"rbcal_version": "0.1.0", "git_revision": "...", "date": "2026-11-21T22:10:47Z",
//    "host": "...", "build_target": "GNU 12.2.0, -march=icelake-server"}
// build_target: the compiler and the CPU -march=native resolved to, with any vector extension
// the host adds to that name ("-march=znver3+avx512f": GCC 12.2 on Zen 4); floating-point
// results reproduce to the last bit only between builds for one target.
// The date is UTC; with SOURCE_DATE_EPOCH set (reproducible builds,
// https://reproducible-builds.org/specs/source-date-epoch/) it is that time instead of
// now, so two runs can write identical files. Writers add their own keys to the block.
#include <nlohmann/json.hpp>
#include <string>

namespace rbcal::formats {

std::string host_name();
std::string utc_date();  // ISO 8601, honouring SOURCE_DATE_EPOCH

nlohmann::json provenance_block();

}  // namespace rbcal::formats
