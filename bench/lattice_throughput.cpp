#include "bench/lattice_throughput.hpp"

#include <omp.h>

#include <cmath>

#include "bench/timing.hpp"
#include "solver/fluid_lattice.hpp"

namespace rbcal::bench {

LatticeThroughputResult measure_lattice_throughput(std::array<int, 3> box, int steps,
                                                   int repetitions) {
  solver::FluidConfig cfg;
  cfg.nx = box[0];
  cfg.ny = box[1];
  cfg.nz = box[2];
  cfg.wall_velocity_bottom = -0.01;
  cfg.wall_velocity_top = 0.01;
  solver::FluidLattice fluid(cfg);

  // A viscosity field with contrast 5 and a small force everywhere, so that no branch
  // or constant folding makes the benchmark cheaper than a real suspension step.
  const std::size_t n = fluid.node_count();
  double* nu = fluid.viscosity();
  for (std::size_t i = 0; i < n; ++i) nu[i] = (1.0 / 6.0) * (1.0 + 4.0 * (0.5 + 0.5 * std::sin(0.37 * i)));
  for (int d = 0; d < 3; ++d) {
    double* f = fluid.force(d);
    for (std::size_t i = 0; i < n; ++i) f[i] = 1e-7 * std::cos(0.11 * i + d);
  }
  fluid.step();  // warm-up: touches both population arrays

  LatticeThroughputResult result;
  result.box = box;
  result.threads = omp_get_max_threads();
  result.steps_per_repetition = steps;
  for (int r = 0; r < repetitions; ++r)
    result.seconds.push_back(seconds_of([&] {
      for (int s = 0; s < steps; ++s) fluid.step();
    }));
  result.median_updates_per_s = static_cast<double>(n) * steps / median(result.seconds);
  return result;
}

}  // namespace rbcal::bench
