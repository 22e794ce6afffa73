#include "solver/coupling/immersed_boundary.hpp"

#include <cmath>
#include <cstdint>
#include <utility>

namespace rbcal::solver {

namespace {

int wrap(int i, int n) { return ((i % n) + n) % n; }

// First node of the support and the weights along one direction. The 2- and 4-point
// weights come in closed form from the fractional position: the four Peskin weights
// share one square root (substitute r + 1, r, 1 - r, 2 - r into the kernel), which
// makes this several times cheaper than four kernel evaluations.
// First lattice node of the support around r: even supports straddle r, the 3-point
// one is centred on the nearest node.
int support_start(KernelKind kernel, double r) {
  const int support = kernel_support(kernel);
  return support == 3 ? static_cast<int>(std::lround(r)) - 1 : static_cast<int>(std::floor(r)) - (support - 1) / 2;
}

void weights_1d(KernelKind kernel, double r, int support, int& first, std::array<double, 4>& w) {
  const double f = std::floor(r);
  const double t = r - f;  // in [0, 1)
  switch (kernel) {
    case KernelKind::Linear2:
      first = static_cast<int>(f);
      w[0] = 1.0 - t;
      w[1] = t;
      return;
    case KernelKind::Peskin4: {
      first = static_cast<int>(f) - 1;
      const double q = std::sqrt(1.0 + 4.0 * t - 4.0 * t * t);
      w[0] = (3.0 - 2.0 * t - q) / 8.0;
      w[1] = (3.0 - 2.0 * t + q) / 8.0;
      w[2] = (1.0 + 2.0 * t + q) / 8.0;
      w[3] = (1.0 + 2.0 * t - q) / 8.0;
      return;
    }
    case KernelKind::Roma3:
      break;
  }
  first = support_start(kernel, r);
  for (int i = 0; i < support; ++i) w[i] = kernel_weight(kernel, r - (first + i));
}

}  // namespace

KernelStencil make_stencil(KernelKind kernel, const Vec3& p, int nx, int ny, int nz) {
  KernelStencil s;
  s.count = kernel_support(kernel);
  int fx, fy, fz;
  weights_1d(kernel, p.x(), s.count, fx, s.wx);
  weights_1d(kernel, p.y(), s.count, fy, s.wy);
  weights_1d(kernel, p.z(), s.count, fz, s.wz);
  // One modulo per direction: the support's later nodes wrap at most once.
  const int x0 = wrap(fx, nx), z0 = wrap(fz, nz);
  double wy_sum = 0.0;
  for (int i = 0; i < s.count; ++i) {
    s.x[i] = x0 + i < nx ? x0 + i : wrap(x0 + i, nx);
    s.z[i] = z0 + i < nz ? z0 + i : wrap(z0 + i, nz);
    s.y[i] = fy + i;
    if (s.y[i] < 0 || s.y[i] >= ny) {
      s.wy[i] = 0.0;  // beyond a wall
      s.y[i] = 0;
    }
    wy_sum += s.wy[i];
  }
  if (wy_sum > 0.0)
    for (int i = 0; i < s.count; ++i) s.wy[i] /= wy_sum;
  return s;
}

namespace {

// Adds one node's force through its stencil.
void spread_one(const KernelStencil& s, const Vec3& force, double* const f[3], const FluidLattice& fluid) {
  for (int a = 0; a < s.count; ++a)
    for (int b = 0; b < s.count; ++b) {
      const double wab = s.wx[a] * s.wy[b];
      if (wab == 0.0) continue;
      const std::size_t row = fluid.index(s.x[a], s.y[b], 0);
      for (int c = 0; c < s.count; ++c) {
        const double w = wab * s.wz[c];
        const std::size_t node = row + s.z[c];
        for (int d = 0; d < 3; ++d) f[d][node] += w * force[d];
      }
    }
}

// Width (in x) of the slabs that spreading colours; at least the widest support less
// one, so that slabs two apart never write the same lattice node.
constexpr int kSlabWidth = 4;

}  // namespace

void spread_forces(KernelKind kernel, const std::vector<std::vector<Vec3>>& positions,
                   const std::vector<std::vector<Vec3>>& forces, FluidLattice& fluid) {
  const int nx = fluid.nx(), ny = fluid.ny(), nz = fluid.nz();
  double* const f[3] = {fluid.force(0), fluid.force(1), fluid.force(2)};
  // Group the nodes by the slab of their stencil's first x column (counting sort). A
  // node's stencil reaches at most support - 1 columns past its slab, so slabs of one
  // parity can spread concurrently: even slabs, then odd ones, then (for an odd slab
  // count) the last slab, which touches slab 0 across the periodic boundary. Within a
  // slab the nodes keep their order, so the sums do not depend on the thread count.
  const int slabs = (nx + kSlabWidth - 1) / kSlabWidth;
  auto slab_of = [&](const Vec3& x) { return wrap(support_start(kernel, x.x()), nx) / kSlabWidth; };
  std::vector<std::size_t> start(slabs + 1, 0);
  for (const auto& cell : positions)
    for (const Vec3& x : cell) ++start[slab_of(x) + 1];
  for (int s = 0; s < slabs; ++s) start[s + 1] += start[s];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ordered(start.back());  // (cell, node) by slab
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t c = 0; c < positions.size(); ++c)
      for (std::size_t n = 0; n < positions[c].size(); ++n)
        ordered[fill[slab_of(positions[c][n])]++] = {static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(n)};
  }
  auto spread_slab = [&](int slab) {
    for (std::size_t g = start[slab]; g < start[slab + 1]; ++g) {
      const auto [c, n] = ordered[g];
      spread_one(make_stencil(kernel, positions[c][n], nx, ny, nz), forces[c][n], f, fluid);
    }
  };
  const bool odd_count = slabs % 2 == 1;
  const int paired = odd_count ? slabs - 1 : slabs;
  for (int parity = 0; parity < 2; ++parity) {
#pragma omp parallel for schedule(dynamic)
    for (int slab = parity; slab < paired; slab += 2) spread_slab(slab);
  }
  if (odd_count) spread_slab(slabs - 1);
}

void spread_forces(KernelKind kernel, const std::vector<Vec3>& positions, const std::vector<Vec3>& forces,
                   FluidLattice& fluid) {
  spread_forces(kernel, std::vector<std::vector<Vec3>>{positions}, std::vector<std::vector<Vec3>>{forces}, fluid);
}

Vec3 interpolate_velocity(KernelKind kernel, const FluidLattice& fluid, const Vec3& position) {
  const KernelStencil s = make_stencil(kernel, position, fluid.nx(), fluid.ny(), fluid.nz());
  return interpolate(s, [&](int i, int j, int k) {
    const NodeMoments m = fluid.moments(fluid.index(i, j, k));
    return Vec3(m.ux, m.uy, m.uz);
  });
}

}  // namespace rbcal::solver
