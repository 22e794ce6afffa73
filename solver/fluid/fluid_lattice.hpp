#pragma once
// D3Q19 lattice-Boltzmann fluid in a box, periodic in x (spanwise) and z (streamwise),
// bounded in y (wall-normal) by two plane walls at y = -1/2 and y = ny - 1/2 (half-way
// bounce-back) that slide along z, or periodic in y for tests. Per-node kinematic
// viscosity and per-node body force (Guo). All quantities in lattice units:
// dx = dt = 1, reference density 1.
//
// Layout: nodes ordered x-major, z fastest (n = (x * ny + y) * nz + z) in every per-node
// field (viscosity, force, velocity). The populations are structure of arrays with each
// row of nz nodes padded to whole cache lines (row_length), so that every row starts on a
// line and is streamed in whole lines: population q of node (x, y, z) at q * stride +
// (x * ny + y) * row_length + z. Unpadded, rows start at every alignment when nz is not a
// multiple of the width, and the update ran 2-3 times slower per node (docs/performance.md). One
// step is a fused pull-stream + TRT collision between two population arrays; the stored
// populations are always post-collision.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "solver/aligned_vector.hpp"

namespace rbcal::solver {

enum class WallNormalBoundary { MovingWalls, Periodic };

struct FluidConfig {
  int nx = 1;
  int ny = 1;
  int nz = 1;
  WallNormalBoundary y_boundary = WallNormalBoundary::MovingWalls;
  double wall_velocity_bottom = 0.0;  // z velocity of the wall at y = -1/2
  double wall_velocity_top = 0.0;     // z velocity of the wall at y = ny - 1/2
  double viscosity = 1.0 / 6.0;       // initial uniform kinematic viscosity
  double magic = 3.0 / 16.0;          // TRT magic parameter Lambda
  // Populations stored in 32 bits as f_q - w_q (the deviation from the fluid at rest, which
  // keeps the float's digits for the part that varies), the update's arithmetic in 64 bits:
  // the scheme FluidX3D published (Lehmann et al., Comput. Phys. Commun. 2022). Halves the
  // update's memory traffic.
  bool single_precision = false;
  // How far ahead of the chunk being loaded every read stream is prefetched, in populations
  // (elements of the storage type: 64 are 512 bytes of doubles, 256 of floats; 0: no
  // software prefetch); one of kPrefetchDistances. A property of the host, not of the
  // results (they are the same at any distance): `rbcal bench --prefetch` measures a host's
  // best.
  int prefetch_distance = 64;
};

// The prefetch distances the update is compiled for (a compile-time constant in its loop:
// read from the configuration inside it, the update ran 1-3 % slower).
inline constexpr std::array<int, 8> kPrefetchDistances = {0, 8, 16, 32, 64, 96, 128, 256};

// Density and the velocity that entered the last collision, u = (sum f* c - F/2) / rho.
struct NodeMoments {
  double rho;
  double ux, uy, uz;
};

// Force per unit area exerted by the fluid on each wall (momentum exchange), lattice units.
struct WallTraction {
  std::array<double, 3> bottom;
  std::array<double, 3> top;
};

class FluidLattice {
 public:
  explicit FluidLattice(const FluidConfig& config);

  const FluidConfig& config() const { return config_; }
  int nx() const { return config_.nx; }
  int ny() const { return config_.ny; }
  int nz() const { return config_.nz; }
  std::size_t node_count() const { return nodes_; }
  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(x) * config_.ny + y) * config_.nz + z;
  }
  std::int64_t steps_done() const { return steps_; }

  // Per-node kinematic viscosity; may be changed between steps (viscosity contrast).
  double* viscosity() { return viscosity_.data(); }
  const double* viscosity() const { return viscosity_.data(); }
  // Per-node body-force density, component 0 = x, 1 = y, 2 = z; applied in the next step.
  double* force(int component) { return force_.data() + component * component_stride_; }
  const double* force(int component) const { return force_.data() + component * component_stride_; }
  // Distance between the components of a three-component per-node field (force,
  // velocity): the node count staggered by five cache lines. When the lattice planes are a
  // multiple of 4 KiB apart (48 x 64 x 48: 24 KiB), unstaggered components put every
  // stencil row of all three in the same L1 set.
  static std::size_t component_stride(std::size_t nodes) { return staggered(nodes, 5); }
  // n elements, per_line to a cache line (8 doubles, 16 floats), rounded up to 4 KiB (one
  // round of L1 sets), plus `lines` cache lines: arrays laid out this far apart start in
  // different L1 sets.
  static std::size_t staggered(std::size_t n, std::size_t lines, std::size_t per_line = 8) {
    const std::size_t four_kib = 64 * per_line;
    return (n + four_kib - 1) / four_kib * four_kib + per_line * lines;
  }
  void clear_force();

  // Puts a node at equilibrium so that moments(node) returns (rho, u) under the
  // current force field.
  void set_equilibrium(std::size_t node, double rho, double ux, double uy, double uz);

  // One time step: pull-stream with the wall conditions, then TRT collision. With
  // velocity_out, also writes each node's velocity u[d][node], equal to moments(node)
  // after the step up to round-off (the immersed boundary's interpolation field, at
  // 24 B per node instead of a second pass over the 19 populations). With accumulate the
  // velocity is added to what velocity_out holds (the sum over a coupling interval).
  void step(double* const velocity_out[3] = nullptr, bool accumulate = false);

  // Sets the prefetch distance (one of kPrefetchDistances; the results do not depend on it).
  void set_prefetch_distance(int distance);
  // Times the update at every compiled prefetch distance on this lattice, `rounds` times
  // each (interleaved, the fastest of each kept), and keeps the fastest distance (the
  // default one unless another is 3 % faster), which it returns. The timed updates write
  // only the step's scratch populations: the state, the step count and every field stay
  // as they were. (They write no velocity field, which coupled steps do: the choice is for
  // the update's population streams.)
  int choose_fastest_prefetch_distance(int rounds = 5);

  NodeMoments moments(std::size_t node) const;
  // The whole state (post-collision populations and step count), for checkpoints, in the
  // unpadded layout q * packed + node (packed: the node count rounded up to the
  // SIMD width), which checkpoints have always used.
  std::vector<double> populations() const;
  void restore(const std::vector<double>& populations, std::int64_t steps);
  double population(int q, std::size_t node) const { return stored(q, padded(node)); }
  double total_mass() const;
  WallTraction wall_traction() const;

 private:
  // Pull-stream and collide the nodes (x, y, 0..nz-1) from cur into next (T: the storage,
  // double or float).
  template <int Ahead, class T>
  void update_row(const T* cur, T* next, int x, int y, double* const velocity_out[3], bool accumulate);
  template <class T>
  using RowUpdate = void (FluidLattice::*)(const T*, T*, int, int, double* const[3], bool);
  // update_row at config_.prefetch_distance.
  template <class T>
  RowUpdate<T> row_update() const;
  // Every row from the current populations into the next ones (no swap).
  void update_rows(double* const velocity_out[3], bool accumulate);
  // Population q at index i of a padded population array, unshifted; and its store.
  double stored(int q, std::size_t i) const {
    return config_.single_precision ? static_cast<double>(h_[q * stride_ + i]) + rest(q) : f_[q * stride_ + i];
  }
  void store(int q, std::size_t i, double value) {
    if (config_.single_precision) h_[q * stride_ + i] = static_cast<float>(value - rest(q));
    else f_[q * stride_ + i] = value;
  }
  static double rest(int q);  // w_q

  // Where node n's populations sit in a padded population array.
  std::size_t padded(std::size_t node) const { return node + node / config_.nz * (row_length_ - config_.nz); }
  std::size_t padded_row(int x, int y) const {
    return (static_cast<std::size_t>(x) * config_.ny + y) * row_length_;
  }

  FluidConfig config_;
  std::size_t nodes_;
  std::size_t component_stride_;  // component_stride(nodes_)
  std::size_t row_length_;  // nz rounded up to whole cache lines
  std::size_t stride_;      // distance between population arrays: nx * ny * row_length_, staggered
  std::int64_t steps_ = 0;
  AlignedVector<double> f_, f_next_;  // populations (double storage)
  AlignedVector<float> h_, h_next_;   // shifted populations (single_precision)
  AlignedVector<double> viscosity_;
  AlignedVector<double> force_;
};

}  // namespace rbcal::solver
