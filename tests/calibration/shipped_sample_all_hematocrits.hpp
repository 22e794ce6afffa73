#pragma once
// The shipped sample with its excluded 55 % rows restored ("#excluded: " prefix removed), as
// the published data set has them, written to the running test's scratch folder.
#include <filesystem>
#include <fstream>
#include <string>

#include "../scratch_path.hpp"

namespace rbcal::calibration::test_models {

inline std::filesystem::path shipped_sample_with_all_hematocrits() {
  const std::string prefix = "#excluded: ";
  const std::filesystem::path out = rbcal::testing_support::scratch_path("kim2017_all_hematocrits.csv");
  std::ifstream in(RBCAL_SAMPLES_DIR "/kim2017_whole_blood.csv");
  std::ofstream copy(out);
  for (std::string line; std::getline(in, line);)
    copy << (line.rfind(prefix, 0) == 0 ? line.substr(prefix.size()) : line) << '\n';
  return out;
}

}  // namespace rbcal::calibration::test_models
