#pragma once
// The fluid update against a memory-bandwidth roofline measured in the same run. The
// two are timed in alternating rounds so that a noisy machine (shared hosts, frequency
// changes) disturbs both alike; the fraction is the median of the per-round ratios.
#include <array>
#include <cstddef>
#include <vector>

namespace rbcal::bench {

struct RooflineSettings {
  std::array<int, 3> box = {256, 160, 256};  // the seed study's box at N_a = 16
  int steps = 5;                             // lattice steps per round
  int rounds = 7;
  bool single_precision = false;  // populations stored in 32 bits
  int prefetch_distance = -1;        // FluidConfig::prefetch_distance (negative: its default)
  std::size_t triad_elements = std::size_t{128} << 20;  // 1 GiB per array
};

struct RooflineResult {
  int threads = 0;
  std::vector<double> triad_bytes_per_s;            // ordinary stores, per round
  std::vector<double> triad_streaming_bytes_per_s;  // streaming stores, per round
  std::vector<double> lattice_updates_per_s;        // per round
  double median_triad = 0, median_triad_streaming = 0, median_updates = 0;
  double fraction_of_triad = 0;            // median of per-round ratios
  double fraction_of_streaming_triad = 0;  // likewise, against the streaming-store triad
  // The process's anonymous memory and its part in huge pages while the arrays were held
  // (host_description.hpp: memory_use).
  double anonymous_bytes = 0, huge_page_bytes = 0;
};

RooflineResult measure_roofline(const RooflineSettings& settings);

}  // namespace rbcal::bench
