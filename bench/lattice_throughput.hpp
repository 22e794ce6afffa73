#pragma once
// Throughput of the production fluid update: D3Q19 TRT with a per-node viscosity
// field and a per-node Guo body force, fused pull-stream, moving walls.
#include <array>
#include <cstddef>
#include <vector>

namespace rbcal::bench {

struct LatticeThroughputResult {
  std::array<int, 3> box{};      // nx, ny, nz
  int threads = 0;
  int steps_per_repetition = 0;
  std::vector<double> seconds;   // one per repetition
  double median_updates_per_s = 0;
  // Bytes each node update must move to and from memory at minimum: 19 populations
  // read and 19 written (8 B each), the viscosity (8 B) and the force (24 B) read.
  static constexpr double bytes_per_update = 19 * 8 * 2 + 8 + 24;
};

LatticeThroughputResult measure_lattice_throughput(std::array<int, 3> box, int steps,
                                                   int repetitions);

}  // namespace rbcal::bench
