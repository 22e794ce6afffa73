#pragma once
// The immersed-boundary kernel's footprint around one point (lattice units, node (i, j, k)
// at (i, j, k)): the first node and the weights along each direction, wrapped in x and z;
// along y, weights that would fall beyond a wall (y < 0 or y >= ny) are dropped and the rest
// renormalised, so that spreading conserves force and interpolation reproduces constants
// next to a wall. Shared by the CPU solver and the device path.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "solver/coupling/peskin_kernel.hpp"
#include "solver/device/host_device.hpp"

namespace rbcal::solver {

// Two cache lines exactly (16-bit indices: lattices up to 32767 nodes a side); built where
// it is used, from a node's position.
struct alignas(64) KernelStencil {
  std::array<double, 4> wx{}, wy{}, wz{};
  std::array<std::int16_t, 4> x{}, y{}, z{};  // lattice indices (wrapped in x and z)
  std::int16_t count = 0;                     // support width
};
static_assert(sizeof(KernelStencil) == 128);

// i wrapped into [0, n) (periodic directions; any i).
RBCAL_HD inline int wrap_index(int i, int n) { return ((i % n) + n) % n; }

// floor(i / n) for n > 0 and any i (integer division rounds toward zero).
RBCAL_HD inline int floor_div(int i, int n) { return i >= 0 ? i / n : -((-i + n - 1) / n); }

// FluidLattice::index for a lattice of ny x nz rows (x-major, z fastest).
RBCAL_HD inline std::size_t lattice_index(int x, int y, int z, int ny, int nz) {
  return (static_cast<std::size_t>(x) * ny + y) * nz + z;
}

// First lattice node of the support around r: even supports straddle r, the 3-point
// one is centred on the nearest node.
RBCAL_HD inline int support_start(KernelKind kernel, double r) {
  const int support = kernel_support(kernel);
  return support == 3 ? static_cast<int>(lround(r)) - 1 : static_cast<int>(floor(r)) - (support - 1) / 2;
}

// The four Peskin weights at fractional position t in [0, 1): they share one square root
// (substitute t + 1, t, 1 - t, 2 - t into the kernel), which makes this several times
// cheaper than four kernel evaluations. (Also run eight nodes at a time, as vectors, by the
// CPU's spreading and interpolation.)
RBCAL_HD inline void peskin4_weights(double t, double& w0, double& w1, double& w2, double& w3) {
  const double q = sqrt(1.0 + 4.0 * t - 4.0 * t * t);
  w0 = (3.0 - 2.0 * t - q) / 8.0;
  w1 = (3.0 - 2.0 * t + q) / 8.0;
  w2 = (1.0 + 2.0 * t + q) / 8.0;
  w3 = (1.0 + 2.0 * t - q) / 8.0;
}

// First node of the support and the weights along one direction. The 2- and 4-point
// weights come in closed form from the fractional position.
RBCAL_HD inline void kernel_weights_1d(KernelKind kernel, double r, int support, int& first, std::array<double, 4>& w) {
  const double f = floor(r);
  const double t = r - f;  // in [0, 1)
  switch (kernel) {
    case KernelKind::Linear2:
      first = static_cast<int>(f);
      w[0] = 1.0 - t;
      w[1] = t;
      return;
    case KernelKind::Peskin4: {
      first = static_cast<int>(f) - 1;
      peskin4_weights(t, w[0], w[1], w[2], w[3]);
      return;
    }
    case KernelKind::Roma3:
      break;
  }
  first = support_start(kernel, r);
  for (int i = 0; i < support; ++i) w[i] = kernel_weight(kernel, r - (first + i));
}

// i >= 0 wrapped into [0, n), without a modulo below 2n (a support starting in the box).
RBCAL_HD inline int wrap_from_box(int i, int n) { return i < n ? i : (i - n < n ? i - n : wrap_index(i, n)); }

// Fills the stencil's lattice indices from its support's first node (x0 and z0 already in
// [0, n): their later nodes wrap by at most one period on lattices at least a support wide)
// and drops the y weights beyond a wall, renormalising the rest; s.count and the weights
// are set. The one place this is done, so that stencils built from the blocks of eight
// (immersed_boundary.cpp) sum to the last bit as make_stencil's do.
RBCAL_HD inline void place_support(KernelStencil& s, int x0, int fy, int z0, int nx, int ny, int nz) {
  bool clipped = false;
  for (int i = 0; i < s.count; ++i) {
    s.x[i] = static_cast<std::int16_t>(wrap_from_box(x0 + i, nx));
    s.z[i] = static_cast<std::int16_t>(wrap_from_box(z0 + i, nz));
    s.y[i] = static_cast<std::int16_t>(fy + i);
    if (s.y[i] < 0 || s.y[i] >= ny) {
      s.wy[i] = 0.0;  // beyond a wall
      s.y[i] = 0;
      clipped = true;
    }
  }
  if (clipped) {
    double wy_sum = 0.0;
    for (int i = 0; i < s.count; ++i) wy_sum += s.wy[i];
    if (wy_sum > 0.0)
      for (int i = 0; i < s.count; ++i) s.wy[i] /= wy_sum;
  }
}

RBCAL_HD inline KernelStencil make_stencil(KernelKind kernel, double px, double py, double pz, int nx, int ny, int nz) {
  KernelStencil s;
  s.count = static_cast<std::int16_t>(kernel_support(kernel));
  int fx, fy, fz;
  kernel_weights_1d(kernel, px, s.count, fx, s.wx);
  kernel_weights_1d(kernel, py, s.count, fy, s.wy);
  kernel_weights_1d(kernel, pz, s.count, fz, s.wz);
  // One modulo per direction, only where the support starts outside the box; its later
  // nodes wrap at most once.
  const int x0 = fx >= 0 && fx < nx ? fx : wrap_index(fx, nx), z0 = fz >= 0 && fz < nz ? fz : wrap_index(fz, nz);
  place_support(s, x0, fy, z0, nx, ny, nz);
  return s;
}

// Calls f(node, weight) for every lattice node of the stencil (node: FluidLattice::index on
// a lattice of ny x nz rows), skipping the rows whose x-y weight is zero (beyond a wall).
template <class F>
RBCAL_HD inline void for_each_stencil_node(const KernelStencil& s, int ny, int nz, F&& f) {
  for (int a = 0; a < s.count; ++a)
    for (int b = 0; b < s.count; ++b) {
      const double wab = s.wx[a] * s.wy[b];
      if (wab == 0.0) continue;
      const std::size_t row = lattice_index(s.x[a], s.y[b], 0, ny, nz);
      for (int c = 0; c < s.count; ++c) f(row + s.z[c], wab * s.wz[c]);
    }
}

}  // namespace rbcal::solver
