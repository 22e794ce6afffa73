#include "solver/coupling/immersed_boundary.hpp"

#include <cmath>

namespace rbcal::solver {

namespace {

int wrap(int i, int n) { return ((i % n) + n) % n; }

// First node of the support and the weights along one direction.
void weights_1d(KernelKind kernel, double r, int support, int& first, std::array<double, 4>& w) {
  // Even supports straddle r; the 3-point one is centred on the nearest node.
  first = support == 3 ? static_cast<int>(std::lround(r)) - 1 : static_cast<int>(std::floor(r)) - (support - 1) / 2;
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
  double wy_sum = 0.0;
  for (int i = 0; i < s.count; ++i) {
    s.x[i] = wrap(fx + i, nx);
    s.z[i] = wrap(fz + i, nz);
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

void spread_forces(KernelKind kernel, const std::vector<Vec3>& positions, const std::vector<Vec3>& forces,
                   FluidLattice& fluid) {
  double* f[3] = {fluid.force(0), fluid.force(1), fluid.force(2)};
  for (std::size_t n = 0; n < positions.size(); ++n) {
    const KernelStencil s = make_stencil(kernel, positions[n], fluid.nx(), fluid.ny(), fluid.nz());
    for (int a = 0; a < s.count; ++a)
      for (int b = 0; b < s.count; ++b) {
        const double wab = s.wx[a] * s.wy[b];
        if (wab == 0.0) continue;
        for (int c = 0; c < s.count; ++c) {
          const double w = wab * s.wz[c];
          const std::size_t node = fluid.index(s.x[a], s.y[b], s.z[c]);
          for (int d = 0; d < 3; ++d) f[d][node] += w * forces[n][d];
        }
      }
  }
}

Vec3 interpolate_velocity(KernelKind kernel, const FluidLattice& fluid, const Vec3& position) {
  const KernelStencil s = make_stencil(kernel, position, fluid.nx(), fluid.ny(), fluid.nz());
  return interpolate(s, [&](int i, int j, int k) {
    const NodeMoments m = fluid.moments(fluid.index(i, j, k));
    return Vec3(m.ux, m.uy, m.uz);
  });
}

}  // namespace rbcal::solver
