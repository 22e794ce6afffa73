// Fuzz target: the sweep plan reader (rbcal.plan/1), which checks every grid point as a case.
#include "formats/json_file.hpp"
#include "fuzz/fuzz_reader.hpp"
#include "solver/sweep/sweep_plan.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rbcal::fuzz::run_reader(data, size, [](const std::string& text) {
    using namespace rbcal;
    solver::sweep_plan_from_json(formats::parse_json_text(text, fuzz::kSource), fuzz::kSource);
  });
}
