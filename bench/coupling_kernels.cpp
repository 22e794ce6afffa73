#include "bench/coupling_kernels.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/detail/timing.hpp"
#include "solver/aligned_vector.hpp"
#include "solver/coupling/immersed_boundary.hpp"
#include "solver/coupling/node_order.hpp"

namespace rbcal::bench {

CouplingKernelTimings time_coupling_kernels(solver::KernelKind kernel, const std::vector<std::vector<solver::Vec3>>& positions,
                                            const std::vector<std::vector<solver::Vec3>>& forces,
                                            solver::FluidLattice& fluid, int passes) {
  if (passes < 1) throw std::invalid_argument("coupling-kernel bench: passes must be >= 1");
  solver::NodeOrder order;
  solver::order_nodes(kernel, positions, forces, fluid.nx(), fluid.ny(), fluid.nz(), order);
  const std::size_t total = order.nodes.size();
  if (total == 0) throw std::invalid_argument("coupling-kernel bench: the case has no membrane nodes");
  // A velocity field laid out as the solver's (components a staggered stride apart).
  const std::size_t stride = solver::FluidLattice::component_stride(fluid.node_count());
  solver::AlignedVector<double> field;
  field.assign(3 * stride, 0.0);
  for (std::size_t i = 0; i < field.size(); ++i) field[i] = 1e-3 * std::sin(1e-3 * static_cast<double>(i));
  const double* const u[3] = {field.data(), field.data() + stride, field.data() + 2 * stride};
  std::vector<solver::Vec3> sampled(total);

  // One thread while timing, the caller's again afterwards (also when a kernel throws).
  struct OneThread {
    int threads = omp_get_max_threads();
    OneThread() { omp_set_num_threads(1); }
    ~OneThread() { omp_set_num_threads(threads); }
  };
  const OneThread one_thread;
  std::vector<double> spreading, interpolation;
  constexpr std::size_t block = 64;  // nodes per call, as the solver's membrane update
  const double per_node = 1e9 / static_cast<double>(total);
  for (int p = 0; p < passes; ++p) {
    fluid.clear_force();
    spreading.push_back(per_node * seconds_of([&] { solver::spread_forces(order, fluid); }));
    interpolation.push_back(per_node * seconds_of([&] {
      for (std::size_t b = 0; b < total; b += block)
        solver::interpolate_sorted(order, b, std::min(total, b + block), u, sampled.data() + b);
    }));
  }
  CouplingKernelTimings out;
  out.nodes = total;
  out.passes = passes;
  out.spreading_median = median(spreading);
  out.spreading_fastest = *std::min_element(spreading.begin(), spreading.end());
  out.interpolation_median = median(interpolation);
  out.interpolation_fastest = *std::min_element(interpolation.begin(), interpolation.end());
  return out;
}

}  // namespace rbcal::bench
