// Fuzz target: the surrogate file reader (rbcal.surrogate/1), then one prediction.
#include <cmath>

#include "formats/json_file.hpp"
#include "fuzz/fuzz_reader.hpp"
#include "surrogate/surrogate_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return rbcal::fuzz::run_reader(data, size, [](const std::string& text) {
    using namespace rbcal;
    const surrogate::ViscositySurrogate s =
        surrogate::surrogate_from_json(formats::parse_json_text(text, fuzz::kSource), fuzz::kSource);
    const surrogate::ParameterRange r = s.range();
    s.predict(0.5 * (r.phi_min + r.phi_max), std::sqrt(r.ca_min * r.ca_max), std::sqrt(r.lambda_min * r.lambda_max));
  });
}
