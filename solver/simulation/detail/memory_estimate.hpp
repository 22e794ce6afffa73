#pragma once
// The memory a case needs at its peak, known before anything is allocated, and the memory
// the machine has to give: a case that cannot fit is refused up front, naming the fields
// that set its size, instead of failing with std::bad_alloc (or swapping) mid-allocation.
#include <cstdint>
#include <string>

#include "formats/host_memory.hpp"
#include "solver/simulation/simulation_case.hpp"

namespace rbcal::solver {

// Measured peak resident size of `rbcal simulate` (with checkpoints, which are assembled in
// memory): about 950 bytes per lattice node (populations, fields, and the checkpoint's copies)
// plus about 13 MB, at 4a boxes of N_a 8 and 16 (memory_estimate.cpp), and the membranes.
std::uint64_t estimated_peak_bytes(const SimulationCase& c);

using formats::available_memory_bytes;

// Empty when the case fits in `available` bytes (0: unknown, always fits); otherwise the
// refusal: how much it needs, the lattice, and the fields to change.
std::string memory_refusal(const SimulationCase& c, std::uint64_t available);

}  // namespace rbcal::solver
