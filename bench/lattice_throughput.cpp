#include "bench/lattice_throughput.hpp"

#include <cmath>

#include "bench/detail/timing.hpp"
#include "solver/fluid/fluid_lattice.hpp"

namespace rbcal::bench {

LatticeThroughput::LatticeThroughput(std::array<int, 3> box, bool single_precision, int prefetch_distance) {
  solver::FluidConfig cfg;
  cfg.single_precision = single_precision;
  if (prefetch_distance >= 0) cfg.prefetch_distance = prefetch_distance;
  cfg.nx = box[0];
  cfg.ny = box[1];
  cfg.nz = box[2];
  cfg.wall_velocity_bottom = -0.01;
  cfg.wall_velocity_top = 0.01;
  fluid_ = std::make_unique<solver::FluidLattice>(cfg);

  // A viscosity field with contrast 5 and a small force everywhere, so that no branch
  // or constant folding makes the benchmark cheaper than a real suspension step.
  const std::size_t n = fluid_->node_count();
  double* nu = fluid_->viscosity();
  for (std::size_t i = 0; i < n; ++i) nu[i] = (1.0 / 6.0) * (1.0 + 4.0 * (0.5 + 0.5 * std::sin(0.37 * i)));
  for (int d = 0; d < 3; ++d) {
    double* f = fluid_->force(d);
    for (std::size_t i = 0; i < n; ++i) f[i] = 1e-7 * std::cos(0.11 * i + d);
  }
  fluid_->step();  // touches both population arrays
}

LatticeThroughput::~LatticeThroughput() = default;

double LatticeThroughput::run_once(int steps) {
  return seconds_of([&] {
    for (int s = 0; s < steps; ++s) fluid_->step();
  });
}

double LatticeThroughput::nodes() const { return static_cast<double>(fluid_->node_count()); }

}  // namespace rbcal::bench
