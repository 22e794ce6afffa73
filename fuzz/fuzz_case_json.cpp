// Fuzz target: the case file reader (rbcal.case/1) and the lattice units it implies.
#include "formats/json_file.hpp"
#include "fuzz/fuzz_reader.hpp"
#include "solver/lattice_units.hpp"
#include "solver/simulation/simulation_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rbcal::fuzz::run_reader(data, size, [](const std::string& text) {
    using namespace rbcal;
    const solver::SimulationCase c =
        solver::case_from_json(formats::parse_json_text(text, fuzz::kSource), fuzz::kSource);
    try {
      solver::derive_lattice_units(c.flow, c.resolution);
    } catch (const std::invalid_argument& e) {
      // A combination the lattice cannot represent: reported for the case, as simulate does.
      throw std::invalid_argument(std::string(fuzz::kSource) + ": " + e.what());
    }
  });
}
