#include "solver/fluid/fluid_lattice.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "solver/fluid/d3q19.hpp"
#include "solver/simd.hpp"
#include "solver/fluid/detail/trt_collision.hpp"

namespace rbcal::solver {

using namespace d3q19;

namespace {

// Floats and doubles in a 64-byte cache line (the rows of the populations are whole lines).
constexpr int kFloatsPerLine = 16;
constexpr int kDoublesPerLine = 8;

// Read, keep in all cache levels (locality 3: a non-temporal hint was 30 % slower).
inline void prefetch(const void* p) { __builtin_prefetch(p, 0, 3); }

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("FluidLattice: " + what);
}

// n rounded up to a multiple of m.
std::size_t round_up(std::size_t n, std::size_t m) { return (n + m - 1) / m * m; }

// n rounded up to a whole number of SIMD vectors: the stride of the checkpoints' unpadded
// population layout (node count rounded up).
std::size_t whole_vectors(std::size_t n) { return round_up(n, simd::width); }

// Equilibrium populations for density rho and velocity u (second order in u).
void equilibrium(double rho, double ux, double uy, double uz, double* feq) {
  const double usq = ux * ux + uy * uy + uz * uz;
  for (int q = 0; q < Q; ++q) {
    const double cu = c[q][0] * ux + c[q][1] * uy + c[q][2] * uz;
    feq[q] = w[q] * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * usq);
  }
}

}  // namespace

FluidLattice::FluidLattice(const FluidConfig& config) : config_(config) {
  require(config.nx >= 1 && config.ny >= 1 && config.nz >= 1, "lattice dimensions must be >= 1");
  require(config.viscosity > 0.0, "viscosity must be positive");
  require(config.magic > 0.0, "TRT magic parameter must be positive");
  set_prefetch_distance(config.prefetch_distance);
  nodes_ = static_cast<std::size_t>(config.nx) * config.ny * config.nz;
  component_stride_ = component_stride(nodes_);
  // Rows of whole cache lines (8 doubles or 16 floats), so that the update streams whole
  // lines whatever the vector width (with 4 doubles per vector, half-line streaming stores
  // made it five times slower).
  const bool single = config.single_precision;
  const std::size_t per_line = single ? kFloatsPerLine : kDoublesPerLine;
  row_length_ = round_up(static_cast<std::size_t>(config.nz), per_line);
  // The population arrays lie three cache lines apart modulo 4 KiB. When the lattice is a
  // multiple of 4 KiB (most are), the 19 streams of a row otherwise share a few L1 sets;
  // staggered, the update is 7 % faster on 256 x 160 x 256 (docs/performance.md). Floats:
  // the same in bytes.
  const std::size_t padded_nodes = static_cast<std::size_t>(config.nx) * config.ny * row_length_;
  stride_ = staggered(padded_nodes, 3, per_line);
  // Zeros: the padding lanes start finite (they never feed a node).
  if (single) {
    h_.resize(Q * stride_);
    h_next_.resize(Q * stride_);
  } else {
    f_.resize(Q * stride_);
    f_next_.resize(Q * stride_);
  }
  // One vector of slack after the per-node fields: the last chunk of the last row loads a
  // full vector of them (lanes past the row are padding and are not used).
  viscosity_.assign(nodes_ + simd::width, config.viscosity);
  force_.assign(3 * component_stride_ + simd::width, 0.0);
  for (std::size_t n = 0; n < nodes_; ++n) set_equilibrium(n, 1.0, 0.0, 0.0, 0.0);
}

void FluidLattice::clear_force() {
  const long n = static_cast<long>(force_.size());
  double* f = force_.data();
#pragma omp parallel for schedule(static) if (n >= 65536)
  for (long i = 0; i < n; ++i) f[i] = 0.0;
}

void FluidLattice::set_equilibrium(std::size_t node, double rho, double ux, double uy, double uz) {
  // Stored populations are post-collision, whose momentum exceeds rho u by F/2.
  const double half_over_rho = 0.5 / rho;
  double feq[Q];
  equilibrium(rho, ux + force(0)[node] * half_over_rho, uy + force(1)[node] * half_over_rho,
              uz + force(2)[node] * half_over_rho, feq);
  for (int q = 0; q < Q; ++q) store(q, padded(node), feq[q]);
}

double FluidLattice::rest(int q) { return w[q]; }

template <int Ahead, class T>
void FluidLattice::update_row(const T* cur, T* next, int x, int y, double* const velocity_out[3], bool accumulate) {
  using simd::vdouble;
  // Float storage holds f_q - w_q: the shift is added on loading, taken off on storing.
  constexpr bool shifted = std::is_same_v<T, float>;
  // Every stream the update reads is prefetched ahead (FluidConfig::prefetch_distance): with
  // 23 read streams per row the hardware prefetchers fall behind. 64 populations ahead lift
  // the update 1.4-1.5 times on both Intel Xeon hosts measured (docs/performance.md,
  // "Software prefetch"). The per-node fields are prefetched as many doubles ahead.
  constexpr int ahead = Ahead;
  constexpr int W = simd::width;
  const int nx = config_.nx, ny = config_.ny, nz = config_.nz;
  const bool walls = config_.y_boundary == WallNormalBoundary::MovingWalls;
  const std::size_t row = index(x, y, 0);  // in the per-node fields
  const std::size_t prow = padded_row(x, y);  // in the population arrays

  // Node z of this row pulls population q from src[q][z - shift[q]] + add[q].
  const T* src[Q];
  int shift[Q];
  double add[Q];
  T* out[Q];
  for (int q = 0; q < Q; ++q) {
    out[q] = next + q * stride_ + prow;
    int ys = y - c[q][1];
    if (walls && (ys < 0 || ys >= ny)) {
      // Half-way bounce-back with the moving-wall term (Ladd 1994):
      // f_q(x, t+1) = f*_qbar(x, t) + 6 w_q (c_q . u_wall).
      const double u_wall = ys < 0 ? config_.wall_velocity_bottom : config_.wall_velocity_top;
      src[q] = cur + opposite(q) * stride_ + prow;
      shift[q] = 0;
      add[q] = 6.0 * w[q] * c[q][2] * u_wall + (shifted ? w[q] : 0.0);
    } else {
      ys = (ys + ny) % ny;
      const int xs = (x - c[q][0] + nx) % nx;
      src[q] = cur + q * stride_ + padded_row(xs, ys);
      shift[q] = c[q][2];
      add[q] = shifted ? w[q] : 0.0;
    }
  }
  const T* in[Q];
  for (int q = 0; q < Q; ++q) in[q] = src[q] - shift[q];

  const double* nu = viscosity_.data() + row;
  const double* fx = force_.data() + row;
  const double* fy = force_.data() + component_stride_ + row;
  const double* fz = force_.data() + 2 * component_stride_ + row;
  // The chunks of a cache line are gathered here (narrowed, for float storage), then
  // streamed as whole lines (simd::store_line_streaming); vectors of a whole line of
  // doubles go straight out.
  constexpr int per_line = shifted ? kFloatsPerLine : kDoublesPerLine;
  constexpr int chunks_per_line = per_line / W;
  constexpr bool staged = chunks_per_line > 1;
  alignas(64) T stage[staged ? Q : 1][per_line];
  // Every padded row starts on a cache line (stride_ and row_length_ are whole lines).
  using vmask = decltype(vdouble{} < vdouble{});
  vdouble lane_index;
  for (int l = 0; l < W; ++l) lane_index[l] = l;

  for (int z0 = 0; z0 < nz; z0 += W) {
    vdouble f[Q], nu_v, fx_v, fy_v, fz_v;
    const bool first = z0 == 0, last = z0 + W >= nz;
    // A chunk of W nodes, the last one reaching into the row's padding when nz is not a
    // multiple of W (rows shorter than W included). In the first and last chunks the
    // populations streaming across the periodic z boundary take one lane from the other
    // end of the row.
    const int real = std::min(W, nz - z0);  // lanes that are nodes
    // Interior chunks (most of a row) cross no seam: their loads unrolled, without the
    // seam's tests (one thread 6-8 % faster at four doubles per vector; within the noise at
    // eight). The first and last chunks take the seam into account.
    if (!first && !last) {
#pragma GCC unroll 19
      for (int q = 0; q < Q; ++q) {
        f[q] = simd::load(in[q] + z0) + add[q];
        if constexpr (ahead > 0) prefetch(in[q] + z0 + ahead);
      }
    } else {
      for (int q = 0; q < Q; ++q) {
        if (first && shift[q] == 1) {
          alignas(simd::bytes) double lanes[W];
          lanes[0] = src[q][nz - 1];
          std::copy(src[q], src[q] + W - 1, lanes + 1);
          f[q] = simd::load(lanes) + add[q];
        } else if (last && shift[q] == -1) {
          alignas(simd::bytes) double lanes[W];
          std::copy(src[q] + z0 + 1, src[q] + z0 + real, lanes);
          lanes[real - 1] = src[q][0];
          std::fill(lanes + real, lanes + W, shifted ? 0.0 : w[q]);  // stored fluid at rest
          f[q] = simd::load(lanes) + add[q];
        } else {
          f[q] = simd::load(in[q] + z0) + add[q];  // the populations that cross no seam
        }
        if constexpr (ahead > 0) prefetch(in[q] + z0 + ahead);
      }
    }
    if constexpr (ahead > 0)
      for (const double* p : {nu, fx, fy, fz}) prefetch(p + z0 + ahead);
    nu_v = simd::load(nu + z0);
    fx_v = simd::load(fx + z0);
    fy_v = simd::load(fy + z0);
    fz_v = simd::load(fz + z0);
    if (real < W) {
      // Padding lanes collide the fluid at rest (finite, never read by a node).
      const vmask pad = lane_index >= static_cast<double>(real);
      for (int q = 0; q < Q; ++q) f[q] = pad ? simd::broadcast(w[q]) : f[q];
      nu_v = pad ? simd::broadcast(config_.viscosity) : nu_v;
      fx_v = pad ? vdouble{} : fx_v;
      fy_v = pad ? vdouble{} : fy_v;
      fz_v = pad ? vdouble{} : fz_v;
    }
    vdouble u[3];
    collide_trt(f, nu_v, config_.magic, fx_v, fy_v, fz_v, velocity_out ? u : nullptr);
    if (velocity_out) {
      for (int d = 0; d < 3; ++d) {
        double* out_u = velocity_out[d] + row + z0;
        if (z0 + W <= nz) simd::store(out_u, accumulate ? simd::load(out_u) + u[d] : u[d]);
        else
          for (int l = 0; z0 + l < nz; ++l) out_u[l] = accumulate ? out_u[l] + u[d][l] : u[d][l];
      }
    }
    if constexpr (staged) {
      const int k = (z0 / W) % chunks_per_line;
      for (int q = 0; q < Q; ++q) simd::store(stage[q] + k * W, shifted ? f[q] - w[q] : f[q]);
      const int line_start = z0 - k * W;
      if (k == chunks_per_line - 1) {
        for (int q = 0; q < Q; ++q) simd::store_line_streaming(out[q] + line_start, stage[q]);
      } else if (last) {  // the row ends inside this line: its chunks so far, ordinary stores
        for (int q = 0; q < Q; ++q) std::copy(stage[q], stage[q] + (k + 1) * W, out[q] + line_start);
      }
    } else {
      // Whole lines into the padded, aligned rows (the padding lanes included).
      for (int q = 0; q < Q; ++q) simd::store_streaming(out[q] + z0, f[q]);
    }
  }
}

template <class T>
FluidLattice::RowUpdate<T> FluidLattice::row_update() const {
  // The instantiation whose distance is the configured one (the constructor checked that
  // there is one).
  RowUpdate<T> update = nullptr;
  [&]<std::size_t... i>(std::index_sequence<i...>) {
    ((config_.prefetch_distance == kPrefetchDistances[i] &&
      (update = &FluidLattice::update_row<kPrefetchDistances[i], T>)),
     ...);
  }(std::make_index_sequence<kPrefetchDistances.size()>{});
  return update;
}

void FluidLattice::set_prefetch_distance(int distance) {
  std::string compiled;
  for (const int d : kPrefetchDistances) compiled += (compiled.empty() ? "" : ", ") + std::to_string(d);
  require(std::find(kPrefetchDistances.begin(), kPrefetchDistances.end(), distance) != kPrefetchDistances.end(),
          "prefetch distance " + std::to_string(distance) + " is not one of " + compiled);
  config_.prefetch_distance = distance;
}

int FluidLattice::choose_fastest_prefetch_distance(int rounds) {
  require(rounds >= 1, "prefetch timing needs at least one round");
  using clock = std::chrono::steady_clock;
  std::array<double, kPrefetchDistances.size()> fastest;
  fastest.fill(std::numeric_limits<double>::infinity());
  // Rounds over all distances rather than all rounds of one distance at a time: a host
  // whose speed drifts then weighs on every distance alike.
  // Each sample repeats the update for at least 10 ms, so that a small lattice's samples are
  // not the timer's and the scheduler's noise; its time is the mean per update.
  constexpr double kSampleSeconds = 0.010;
  for (int r = 0; r < rounds; ++r)
    for (std::size_t i = 0; i < kPrefetchDistances.size(); ++i) {
      config_.prefetch_distance = kPrefetchDistances[i];
      const auto start = clock::now();
      double elapsed = 0.0;
      int updates = 0;
      do {
        update_rows(nullptr, false);
        ++updates;
        elapsed = std::chrono::duration<double>(clock::now() - start).count();
      } while (elapsed < kSampleSeconds);
      fastest[i] = std::min(fastest[i], elapsed / updates);
    }
  // The default distance unless another is clearly (3 %) faster: within that the samples'
  // noise, not the host, would choose.
  const std::size_t best = static_cast<std::size_t>(std::min_element(fastest.begin(), fastest.end()) - fastest.begin());
  constexpr std::size_t standard = static_cast<std::size_t>(
      std::find(kPrefetchDistances.begin(), kPrefetchDistances.end(), FluidConfig{}.prefetch_distance) -
      kPrefetchDistances.begin());
  static_assert(standard < kPrefetchDistances.size(), "the default prefetch distance is a compiled one");
  config_.prefetch_distance = kPrefetchDistances[fastest[standard] <= 1.03 * fastest[best] ? standard : best];
  return config_.prefetch_distance;
}

void FluidLattice::update_rows(double* const velocity_out[3], bool accumulate) {
  const int nx = config_.nx, ny = config_.ny;
  const RowUpdate<double> update_double = row_update<double>();
  const RowUpdate<float> update_float = row_update<float>();
  // Below a few thousand nodes a thread team costs more than it saves.
  const bool threaded = nodes_ >= 4096;
#pragma omp parallel if (threaded)
  {
#pragma omp for collapse(2) schedule(static) nowait
    for (int x = 0; x < nx; ++x)
      for (int y = 0; y < ny; ++y) {
        if (config_.single_precision) (this->*update_float)(h_.data(), h_next_.data(), x, y, velocity_out, accumulate);
        else (this->*update_double)(f_.data(), f_next_.data(), x, y, velocity_out, accumulate);
      }
    simd::store_fence();  // streaming stores visible before the barrier
  }
}

void FluidLattice::step(double* const velocity_out[3], bool accumulate) {
  update_rows(velocity_out, accumulate);
  f_.swap(f_next_);
  h_.swap(h_next_);
  ++steps_;
}

std::vector<double> FluidLattice::populations() const {
  const std::size_t packed = whole_vectors(nodes_);
  std::vector<double> out(Q * packed, 0.0);
  for (int q = 0; q < Q; ++q)
    for (std::size_t n = 0; n < nodes_; ++n) out[q * packed + n] = stored(q, padded(n));
  return out;
}

void FluidLattice::restore(const std::vector<double>& populations, std::int64_t steps) {
  const std::size_t packed = whole_vectors(nodes_);
  require(populations.size() == Q * packed, "checkpoint holds " + std::to_string(populations.size()) +
                                                " populations, the lattice needs " + std::to_string(Q * packed));
  for (int q = 0; q < Q; ++q)
    for (std::size_t n = 0; n < nodes_; ++n) store(q, padded(n), populations[q * packed + n]);
  steps_ = steps;
}

NodeMoments FluidLattice::moments(std::size_t node) const {
  double rho = 0.0, jx = 0.0, jy = 0.0, jz = 0.0;
  for (int q = 0; q < Q; ++q) {
    const double fq = stored(q, padded(node));
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
  for (int q = 0; q < Q; ++q) {
    const long n = static_cast<long>(nodes_);
#pragma omp parallel for reduction(+ : mass) schedule(static)
    for (long i = 0; i < n; ++i) mass += stored(q, padded(static_cast<std::size_t>(i)));
  }
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
        const std::size_t row = padded_row(x, y);
        for (int z = 0; z < config_.nz; ++z) exchanged += 2.0 * stored(q, row + z) - correction;
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
