// Fuzz target: the case file reader (rbcal.case/1), which also derives the case's lattice.
#include "formats/json_file.hpp"
#include "fuzz/fuzz_reader.hpp"
#include "solver/simulation/simulation_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rbcal::fuzz::run_reader(data, size, [](const std::string& text) {
    using namespace rbcal;
    solver::case_from_json(formats::parse_json_text(text, fuzz::kSource), fuzz::kSource);
  });
}
