#pragma once
// The immersed boundary's two kernels on their own, per membrane node: the spreading of the
// nodes' forces onto the lattice and the interpolation of a velocity field at the nodes, over
// a case's cells as they stand, on one thread. Their cost per node depends on the core, not
// on the memory bandwidth whose swings blur the coupled step's parts on shared hosts, so
// alternating runs of two builds compare these kernels within a few per cent (over hours a
// shared host's cores drift too).
#include <cstddef>
#include <vector>

#include "solver/coupling/peskin_kernel.hpp"
#include "solver/fluid/fluid_lattice.hpp"
#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::bench {

struct CouplingKernelTimings {
  std::size_t nodes = 0;
  int passes = 0;
  // Nanoseconds per node and pass: the median over passes, and the fastest pass.
  double spreading_median = 0, spreading_fastest = 0;
  double interpolation_median = 0, interpolation_fastest = 0;
};

// `passes` alternating passes of the sorted nodes' spreading into `lattice`'s force field
// (cleared before each, untimed; the caller's lattice, whose force field this overwrites)
// and interpolation (of a smooth made-up field of its size), on one thread. The nodes are
// sorted and gathered once, as the solver does at an inside-fraction build.
CouplingKernelTimings time_coupling_kernels(solver::KernelKind kernel, const std::vector<std::vector<solver::Vec3>>& positions,
                                            const std::vector<std::vector<solver::Vec3>>& forces,
                                            solver::FluidLattice& lattice, int passes);

}  // namespace rbcal::bench
