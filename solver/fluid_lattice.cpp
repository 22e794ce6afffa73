#include "solver/fluid_lattice.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "solver/d3q19.hpp"
#include "solver/trt_collision.hpp"

namespace rbcal::solver {

using namespace d3q19;

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("FluidLattice: " + what);
}

// Equilibrium populations for density rho and velocity u (second order in u).
void equilibrium(double rho, double ux, double uy, double uz, double* feq) {
  const double usq = ux * ux + uy * uy + uz * uz;
  for (int q = 0; q < Q; ++q) {
    const double cu = c[q][0] * ux + c[q][1] * uy + c[q][2] * uz;
    feq[q] = w[q] * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * usq);
  }
}

// out[z] = src[(z - shift) mod nz] for shift in {-1, 0, 1}: streaming along z.
void copy_shifted(const double* src, double* out, int nz, int shift) {
  if (shift == 0) {
    std::copy(src, src + nz, out);
  } else if (shift == 1) {
    out[0] = src[nz - 1];
    std::copy(src, src + nz - 1, out + 1);
  } else {
    std::copy(src + 1, src + nz, out);
    out[nz - 1] = src[0];
  }
}

}  // namespace

FluidLattice::FluidLattice(const FluidConfig& config) : config_(config) {
  require(config.nx >= 1 && config.ny >= 1 && config.nz >= 1, "lattice dimensions must be >= 1");
  require(config.viscosity > 0.0, "viscosity must be positive");
  require(config.magic > 0.0, "TRT magic parameter must be positive");
  nodes_ = static_cast<std::size_t>(config.nx) * config.ny * config.nz;
  f_.resize(Q * nodes_);
  f_next_.resize(Q * nodes_);
  viscosity_.assign(nodes_, config.viscosity);
  force_.assign(3 * nodes_, 0.0);
  for (std::size_t n = 0; n < nodes_; ++n) set_equilibrium(n, 1.0, 0.0, 0.0, 0.0);
}

void FluidLattice::clear_force() { std::fill(force_.begin(), force_.end(), 0.0); }

void FluidLattice::set_equilibrium(std::size_t node, double rho, double ux, double uy, double uz) {
  // Stored populations are post-collision, whose momentum exceeds rho u by F/2.
  const double half_over_rho = 0.5 / rho;
  double feq[Q];
  equilibrium(rho, ux + force(0)[node] * half_over_rho, uy + force(1)[node] * half_over_rho,
              uz + force(2)[node] * half_over_rho, feq);
  for (int q = 0; q < Q; ++q) f_[q * nodes_ + node] = feq[q];
}

void FluidLattice::gather_row(int x, int y, double* row_buffer) const {
  const int nx = config_.nx, ny = config_.ny, nz = config_.nz;
  const bool walls = config_.y_boundary == WallNormalBoundary::MovingWalls;
  for (int q = 0; q < Q; ++q) {
    double* out = row_buffer + static_cast<std::size_t>(q) * nz;
    int ys = y - c[q][1];
    if (walls && (ys < 0 || ys >= ny)) {
      // Half-way bounce-back with the moving-wall term (Ladd 1994):
      // f_q(x, t+1) = f*_qbar(x, t) + 6 w_q (c_q . u_wall).
      const double u_wall = ys < 0 ? config_.wall_velocity_bottom : config_.wall_velocity_top;
      const double add = 6.0 * w[q] * c[q][2] * u_wall;
      const double* src = f_.data() + opposite(q) * nodes_ + index(x, y, 0);
      for (int z = 0; z < nz; ++z) out[z] = src[z] + add;
    } else {
      ys = (ys + ny) % ny;
      const int xs = (x - c[q][0] + nx) % nx;
      copy_shifted(f_.data() + q * nodes_ + index(xs, ys, 0), out, nz, c[q][2]);
    }
  }
}

void FluidLattice::collide_row(int x, int y, const double* row_buffer) {
  const int nz = config_.nz;
  const double magic = config_.magic;
  const std::size_t row = index(x, y, 0);
  const std::size_t n = nodes_;
  const double* __restrict nu = viscosity_.data() + row;
  const double* __restrict fx = force_.data() + row;
  const double* __restrict fy = force_.data() + n + row;
  const double* __restrict fz = force_.data() + 2 * n + row;
  double* __restrict dst = f_next_.data() + row;
#pragma omp simd
  for (int z = 0; z < nz; ++z) {
    double f[Q];
    for (int q = 0; q < Q; ++q) f[q] = row_buffer[static_cast<std::size_t>(q) * nz + z];
    collide_trt(f, nu[z], magic, fx[z], fy[z], fz[z]);
    for (int q = 0; q < Q; ++q) dst[q * n + z] = f[q];
  }
}

void FluidLattice::step() {
  const int nx = config_.nx, ny = config_.ny, nz = config_.nz;
  // Below a few thousand nodes a thread team costs more than it saves.
  const bool threaded = nodes_ >= 4096;
#pragma omp parallel if (threaded)
  {
    std::vector<double> row_buffer(static_cast<std::size_t>(Q) * nz);
#pragma omp for collapse(2) schedule(static)
    for (int x = 0; x < nx; ++x) {
      for (int y = 0; y < ny; ++y) {
        gather_row(x, y, row_buffer.data());
        collide_row(x, y, row_buffer.data());
      }
    }
  }
  f_.swap(f_next_);
  ++steps_;
}

NodeMoments FluidLattice::moments(std::size_t node) const {
  double rho = 0.0, jx = 0.0, jy = 0.0, jz = 0.0;
  for (int q = 0; q < Q; ++q) {
    const double fq = f_[q * nodes_ + node];
    rho += fq;
    jx += fq * c[q][0];
    jy += fq * c[q][1];
    jz += fq * c[q][2];
  }
  return {rho, (jx - 0.5 * force(0)[node]) / rho, (jy - 0.5 * force(1)[node]) / rho,
          (jz - 0.5 * force(2)[node]) / rho};
}

double FluidLattice::total_mass() const {
  double mass = 0.0;
  const std::size_t total = f_.size();
#pragma omp parallel for reduction(+ : mass) schedule(static)
  for (std::size_t i = 0; i < total; ++i) mass += f_[i];
  return mass;
}

WallTraction FluidLattice::wall_traction() const {
  WallTraction traction{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  if (config_.y_boundary != WallNormalBoundary::MovingWalls) return traction;
  // A population f*_q leaving a wall node towards the wall returns as
  // f*_q - 6 w_q (c_q . u_wall); the wall receives c_q times their sum.
  auto accumulate = [&](int y, int toward_wall, double u_wall, std::array<double, 3>& sum) {
    for (int q = 0; q < Q; ++q) {
      if (c[q][1] != toward_wall) continue;
      const double correction = 6.0 * w[q] * c[q][2] * u_wall;
      double exchanged = 0.0;
      for (int x = 0; x < config_.nx; ++x) {
        const double* fq = f_.data() + q * nodes_ + index(x, y, 0);
        for (int z = 0; z < config_.nz; ++z) exchanged += 2.0 * fq[z] - correction;
      }
      for (int d = 0; d < 3; ++d) sum[d] += c[q][d] * exchanged;
    }
    const double area = static_cast<double>(config_.nx) * config_.nz;
    for (double& s : sum) s /= area;
  };
  accumulate(0, -1, config_.wall_velocity_bottom, traction.bottom);
  accumulate(config_.ny - 1, +1, config_.wall_velocity_top, traction.top);
  return traction;
}

}  // namespace rbcal::solver
