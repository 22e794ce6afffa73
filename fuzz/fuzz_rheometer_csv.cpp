// Fuzz target: the rheometer CSV reader and the relative viscosities made from it.
#include <sstream>

#include "calibration/calibration_input.hpp"
#include "calibration/rheometer_data.hpp"
#include "fuzz/fuzz_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rbcal::fuzz::run_reader(data, size, [](const std::string& text) {
    std::istringstream in(text);
    const auto parsed = rbcal::calibration::parse_rheometer_csv(in, rbcal::fuzz::kSource);
    rbcal::calibration::make_calibration_input(parsed);
  });
}
