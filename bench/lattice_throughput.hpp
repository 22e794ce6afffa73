#pragma once
// The production fluid update set up for timing: D3Q19 TRT with a per-node viscosity
// field (contrast 5) and a per-node Guo body force, fused pull-stream, sliding walls.
#include <array>
#include <memory>

namespace rbcal::solver {
class FluidLattice;
}

namespace rbcal::bench {

class LatticeThroughput {
 public:
  // single_precision: populations stored in 32 bits (FluidConfig::single_precision);
  // prefetch_distance: FluidConfig::prefetch_distance (negative: its default).
  explicit LatticeThroughput(std::array<int, 3> box, bool single_precision = false, int prefetch_distance = -1);
  ~LatticeThroughput();

  // Seconds for `steps` time steps.
  double run_once(int steps);
  double nodes() const;
  // Bytes each node update must move to and from memory at minimum: 19 populations
  // read and 19 written (8 B each), the viscosity (8 B) and the force (24 B) read.
  static constexpr double bytes_per_update = 19 * 8 * 2 + 8 + 24;
  // The same with the populations in 4 bytes.
  static constexpr double bytes_per_update_single = 19 * 4 * 2 + 8 + 24;

 private:
  std::unique_ptr<solver::FluidLattice> fluid_;
};

}  // namespace rbcal::bench
