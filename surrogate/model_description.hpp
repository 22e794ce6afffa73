#pragma once
// What a built model looks like, as `rbcal surrogate build`, `rbcal surrogate family` and the
// model build print it: a surrogate's hyper-parameters, range, sd scale and mean; a family's
// prior, box correction, common range and its members at one probe point.
#include <optional>
#include <string>

#include "surrogate/offset_family.hpp"
#include "surrogate/viscosity_surrogate.hpp"

namespace rbcal::surrogate {

std::string describe_surrogate(const ViscositySurrogate& s);

// box_source: where the box correction's numbers come from (printed when the family has one).
std::string describe_family(const OffsetFamilyModel& family, const std::string& box_source);

}  // namespace rbcal::surrogate
