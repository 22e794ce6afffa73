#include "solver/coupling/immersed_boundary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace rbcal::solver {

namespace {

// Four consecutive doubles as one vector: the z rows of the 4-point stencil.
using v4d = double __attribute__((vector_size(4 * sizeof(double))));

v4d load4(const double* p) {
  v4d v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

void store4(double* p, v4d v) { std::memcpy(p, &v, sizeof v); }

// True where the stencil's z nodes are four consecutive lattice nodes (no seam).
bool contiguous_z4(const KernelStencil& s) { return s.count == 4 && s.z[3] == s.z[0] + 3; }

// A 4-point support across the periodic z seam: its first K nodes end the row (z = nz - K,
// ..., nz - 1), the others begin it. Its rows are read as the row's last four nodes (t) and
// its first four (h), whose lanes line up with the support's as below, so that each lane
// gets the arithmetic of a support of whole rows (for the spreading, rows of at least 8
// nodes, so that t and h do not overlap). 3 of every nz nodes lie across the seam (6-7 % of
// the bench case's, on rows of 48); taken node by node through make_stencil's stencil and a
// 64-term sum, each cost the interpolation about 5 times a node of whole rows.
int seam_tail(const KernelStencil& s, int nz) { return s.count == 4 && s.z[3] != s.z[0] + 3 ? nz - s.z[0] : 0; }
// The support's lanes from (t, h): __builtin_shufflevector's lanes 0-3 are its first
// argument's, 4-7 its second's.
template <int K>
v4d support_lanes(v4d t, v4d h) {
  return __builtin_shufflevector(t, h, 4 - K, 5 - K, 6 - K, 7 - K);
}
// The support's lanes v moved into t's lanes (zero in the others), and into h's.
template <int K>
v4d tail_lanes(v4d v) {
  return __builtin_shufflevector(v, v4d{}, K >= 4 ? K - 4 : 4, K >= 3 ? K - 3 : 4, K >= 2 ? K - 2 : 4, K - 1);
}
template <int K>
v4d head_lanes(v4d v) {
  return __builtin_shufflevector(v, v4d{}, K, K <= 2 ? K + 1 : 4, K <= 1 ? K + 2 : 4, 4);
}

// The 4-point stencils of up to kBlock sorted nodes, direction by direction and laid out by
// node, so that their arithmetic (a floor and a square root per direction) runs across the
// nodes as vectors; make_stencil's weights (peskin4_weights) and its wrapped indices.
constexpr int kBlock = 8;
struct Peskin4Block {
  double w[3][4][kBlock];  // direction, weight, node
  int first[3][kBlock];    // the support's first lattice index: wrapped into the box in x and z
};

void peskin4_block(const Vec3* p, int n, int nx, int nz, Peskin4Block& b) {
  // The coordinates first gathered into whole rows of kBlock (a short block repeats its last
  // node), and the floor taken through an integer conversion: GCC 12 leaves a loop with
  // std::floor scalar (it vectorises it only without trapping math).
  // A node with a coordinate beyond +-2^20 (or NaN: a blown-up membrane) is taken as lying
  // at -2^20 in every direction, which puts its support below the wall y = 0, so it is not
  // on_fast_path() and goes through make_stencil as before; its integer conversions below
  // stay defined.
  constexpr double far = 1048576.0;
  alignas(64) double r[3][kBlock];
  const double* const q = p[0].data();  // Vec3 holds three packed doubles
  if (n == kBlock) {
#pragma omp simd
    for (int i = 0; i < kBlock; ++i)
      for (int d = 0; d < 3; ++d) r[d][i] = q[3 * i + d];
  } else {
    for (int i = 0; i < kBlock; ++i)
      for (int d = 0; d < 3; ++d) r[d][i] = q[3 * std::min(i, n - 1) + d];
  }
  // The range checks as vectors: written as scalar stores read back as a vector, they
  // stalled on store forwarding; written with && (two compares a coordinate), GCC left them
  // scalar, with branches (the kernels 2-3 % dearer).
#pragma omp simd
  for (int i = 0; i < kBlock; ++i) {
    const bool in_x = std::fabs(r[0][i]) < far, in_y = std::fabs(r[1][i]) < far,
               in_z = std::fabs(r[2][i]) < far;  // false for NaN
    r[0][i] = in_x ? r[0][i] : -far;
    r[2][i] = in_z ? r[2][i] : -far;
    r[1][i] = (in_x & in_y & in_z) ? r[1][i] : -far;
  }
  for (int d = 0; d < 3; ++d) {
    double* const w0 = b.w[d][0];
    double* const w1 = b.w[d][1];
    double* const w2 = b.w[d][2];
    double* const w3 = b.w[d][3];
    int* const first = b.first[d];
#pragma omp simd
    for (int i = 0; i < kBlock; ++i) {
      const int truncated = static_cast<int>(r[d][i]);  // |r| <= 2^20
      const int floor_r = truncated - (r[d][i] < truncated);
      peskin4_weights(r[d][i] - floor_r, w0[i], w1[i], w2[i], w3[i]);
      first[i] = floor_r - 1;
    }
  }
  // Cells leave the box in x as they are sheared (positions are unwrapped), so most nodes
  // of a long run lie outside it: their first index is wrapped in x and z as make_stencil
  // wraps it, into [0, m). The quotient through a multiplication (not a division) and a
  // truncation is at most one off (|f| <= 2^20 + 2), which the two corrections take back.
  for (const auto& [d, box] : {std::pair{0, nx}, std::pair{2, nz}}) {
    const int m = box;  // a plain local: clang does not take a structured binding into an OpenMP loop
    int* const first = b.first[d];
    const double inv_m = 1.0 / m;
#pragma omp simd
    for (int i = 0; i < kBlock; ++i) {
      int wrapped = first[i] - m * static_cast<int>(first[i] * inv_m);
      wrapped += wrapped < 0 ? m : 0;
      wrapped -= wrapped >= m ? m : 0;
      first[i] = wrapped;
    }
  }
}

// Whether node i's stencil is one of plain rows: z contiguous (no periodic seam in z) and
// no wall in y; x may wrap (the row planes are taken modulo nx: x_planes). Only lattices at
// least a support wide in x wrap each plane at most once.
bool on_fast_path(const Peskin4Block& b, int i, int nx, int ny, int nz) {
  const int x = b.first[0][i], y = b.first[1][i], z = b.first[2][i];
  return nx >= 4 && x >= 0 && x < nx && y >= 0 && y + 3 < ny && z >= 0 && z + 3 < nz;
}

// The K of a support of plain rows but for the periodic z seam (seam_tail), or 0: no wall in
// y, rows of at least 8 nodes.
int on_seam_path(const Peskin4Block& b, int i, int nx, int ny, int nz) {
  const int x = b.first[0][i], y = b.first[1][i], z = b.first[2][i];
  return nx >= 4 && nz >= 8 && x >= 0 && x < nx && y >= 0 && y + 3 < ny && z + 3 >= nz && z < nz ? nz - z : 0;
}

// The offsets of the stencil's four x planes (plane = ny nz nodes), wrapped.
void x_planes(const Peskin4Block& b, int i, int nx, std::size_t plane, std::size_t out[4]) {
  const int x = b.first[0][i];
  if (x + 3 < nx) {  // most nodes: no seam (a branch: selects for every node cost the interpolation 1-2 %)
    for (int a = 0; a < 4; ++a) out[a] = static_cast<std::size_t>(x + a) * plane;
    return;
  }
  for (int a = 0; a < 4; ++a) out[a] = static_cast<std::size_t>(x + a < nx ? x + a : x + a - nx) * plane;
}

// make_stencil's stencil of node i, built from the block's weights and wrapped first indices
// (no square roots), for a support that meets a wall or the periodic seam in z: placed and
// clipped at the walls by make_stencil's own place_support, so that the sums are the same to
// the last bit. False where the node needs make_stencil: lattices narrower than a support in
// x or z, or a support wholly beyond a wall (a blown-up node: peskin4_block puts it there).
bool block_stencil(const Peskin4Block& b, int i, int nx, int ny, int nz, KernelStencil& s) {
  const int x = b.first[0][i], y = b.first[1][i], z = b.first[2][i];
  if (nx < 4 || nz < 4 || x < 0 || x >= nx || z < 0 || z >= nz || y + 3 < 0 || y >= ny) return false;
  s.count = 4;
  for (int c = 0; c < 4; ++c) {
    s.wx[c] = b.w[0][c][i];
    s.wy[c] = b.w[1][c][i];
    s.wz[c] = b.w[2][c][i];
  }
  place_support(s, x, y, z, nx, ny, nz);
  return true;
}

// The stencil of sorted node g (node i of its block) off the block's plain rows.
KernelStencil edge_stencil(const Peskin4Block& b, int i, const NodeOrder& order, std::size_t g) {
  KernelStencil s;
  return block_stencil(b, i, order.nx, order.ny, order.nz, s) ? s : order.stencil_of(g);
}

// Sorted nodes often share their first lattice node with the one before (about 30 % of them
// on the bench case); the spreading reads and writes the rows of such a run once (the
// spreading 11 % cheaper; reading them once for the interpolation saved nothing
// measurable). The length of the run from node i, at most kMaxRun (longer runs go on as
// further runs).
constexpr int kMaxRun = 3;
int run_length(const Peskin4Block& b, int i, int n) {
  int j = i + 1;
  while (j < n && j < i + kMaxRun && b.first[0][j] == b.first[0][i] && b.first[1][j] == b.first[1][i] &&
         b.first[2][j] == b.first[2][i])
    ++j;
  return j - i;
}

// Adds the forces of nodes i, ..., i + N - 1 of the block (one run on the fast path) row by
// row: each row gets the nodes' contributions one after the other, as N single nodes would
// give them, so the sums are the same to the last bit.
template <int N>
void spread_rows(const Peskin4Block& b, int i, const Vec3* force, double* const f[3], int nx, int ny, int nz) {
  std::size_t planes[4];
  x_planes(b, i, nx, static_cast<std::size_t>(ny) * nz, planes);
  const std::size_t yz = static_cast<std::size_t>(b.first[1][i]) * nz + b.first[2][i];
  v4d fz[N][3];
  for (int n = 0; n < N; ++n) {
    const v4d wz = {b.w[2][0][i + n], b.w[2][1][i + n], b.w[2][2][i + n], b.w[2][3][i + n]};
    for (int d = 0; d < 3; ++d) fz[n][d] = wz * force[n][d];
  }
  double* const f0 = f[0];
  double* const f1 = f[1];
  double* const f2 = f[2];
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) {
      const std::size_t at = planes[a] + yz + c * static_cast<std::size_t>(nz);
      v4d r0 = load4(f0 + at), r1 = load4(f1 + at), r2 = load4(f2 + at);
      for (int n = 0; n < N; ++n) {
        const double wab = b.w[0][a][i + n] * b.w[1][c][i + n];
        r0 += wab * fz[n][0];
        r1 += wab * fz[n][1];
        r2 += wab * fz[n][2];
      }
      store4(f0 + at, r0);
      store4(f1 + at, r1);
      store4(f2 + at, r2);
    }
}

// A support across the z seam (its first K z nodes end the row), row by row: for_each_row(add)
// calls add(w_xy, row) for each of its (x, y) rows, row the lattice index of the row's z = 0
// node. The interpolation sums each lane of the row ends as a support of whole rows does
// (interpolate_rows), then moves the lanes into the support's.
template <int K, class ForEachRow>
Vec3 interpolate_row_ends(ForEachRow&& for_each_row, const v4d& wz, const double* const u[3], int nz) {
  const double* const u0 = u[0];
  const double* const u1 = u[1];
  const double* const u2 = u[2];
  v4d t0 = {}, t1 = {}, t2 = {}, h0 = {}, h1 = {}, h2 = {};
  for_each_row([&](double wab, std::size_t row) {
    const std::size_t tail = row + nz - 4;
    t0 += wab * load4(u0 + tail);
    t1 += wab * load4(u1 + tail);
    t2 += wab * load4(u2 + tail);
    h0 += wab * load4(u0 + row);
    h1 += wab * load4(u1 + row);
    h2 += wab * load4(u2 + row);
  });
  const v4d v0 = support_lanes<K>(t0, h0) * wz, v1 = support_lanes<K>(t1, h1) * wz, v2 = support_lanes<K>(t2, h2) * wz;
  return Vec3((v0[0] + v0[1]) + (v0[2] + v0[3]), (v1[0] + v1[1]) + (v1[2] + v1[3]), (v2[0] + v2[1]) + (v2[2] + v2[3]));
}

// The spreading of one such node: w_xy (w_z f) into its lanes of each row end, as a support of
// whole rows adds it (spread_rows, spread_one); the row ends' other lanes get + 0.0. Rows of at
// least 8 nodes, so that the two ends do not overlap.
template <int K, class ForEachRow>
void spread_row_ends(ForEachRow&& for_each_row, const v4d& wz, const Vec3& force, double* const f[3], int nz) {
  double* const f0 = f[0];
  double* const f1 = f[1];
  double* const f2 = f[2];
  const v4d fz0 = wz * force[0], fz1 = wz * force[1], fz2 = wz * force[2];
  const v4d t0 = tail_lanes<K>(fz0), t1 = tail_lanes<K>(fz1), t2 = tail_lanes<K>(fz2);
  const v4d h0 = head_lanes<K>(fz0), h1 = head_lanes<K>(fz1), h2 = head_lanes<K>(fz2);
  for_each_row([&](double wab, std::size_t row) {
    const std::size_t tail = row + nz - 4;
    store4(f0 + tail, load4(f0 + tail) + wab * t0);
    store4(f1 + tail, load4(f1 + tail) + wab * t1);
    store4(f2 + tail, load4(f2 + tail) + wab * t2);
    store4(f0 + row, load4(f0 + row) + wab * h0);
    store4(f1 + row, load4(f1 + row) + wab * h1);
    store4(f2 + row, load4(f2 + row) + wab * h2);
  });
}

// The rows of node i of a block on the seam path (on_seam_path), from the block's weights.
auto block_rows(const Peskin4Block& b, int i, int nx, int ny, int nz) {
  return [&b, i, nx, ny, nz](auto&& add) {
    std::size_t planes[4];
    x_planes(b, i, nx, static_cast<std::size_t>(ny) * nz, planes);
    const std::size_t y0 = static_cast<std::size_t>(b.first[1][i]) * nz;
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 4; ++c) add(b.w[0][a][i] * b.w[1][c][i], planes[a] + y0 + c * static_cast<std::size_t>(nz));
  };
}
v4d block_wz(const Peskin4Block& b, int i) { return v4d{b.w[2][0][i], b.w[2][1][i], b.w[2][2][i], b.w[2][3][i]}; }

// The rows of a 4-point stencil with a weight (those beyond a wall have none).
auto stencil_rows(const KernelStencil& s, int ny, int nz) {
  return [&s, ny, nz](auto&& add) {
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const double wab = s.wx[a] * s.wy[b];
        if (wab != 0.0) add(wab, lattice_index(s.x[a], s.y[b], 0, ny, nz));
      }
  };
}
v4d stencil_wz(const KernelStencil& s) { return v4d{s.wz[0], s.wz[1], s.wz[2], s.wz[3]}; }

Vec3 interpolate_rows(const Peskin4Block& b, int i, const double* const u[3], int nx, int ny, int nz) {
  std::size_t planes[4];
  x_planes(b, i, nx, static_cast<std::size_t>(ny) * nz, planes);
  const std::size_t yz = static_cast<std::size_t>(b.first[1][i]) * nz + b.first[2][i];
  const double* const u0 = u[0];
  const double* const u1 = u[1];
  const double* const u2 = u[2];
  v4d sum0 = {}, sum1 = {}, sum2 = {};
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 4; ++c) {
      const double wab = b.w[0][a][i] * b.w[1][c][i];
      const std::size_t at = planes[a] + yz + c * static_cast<std::size_t>(nz);
      sum0 += wab * load4(u0 + at);
      sum1 += wab * load4(u1 + at);
      sum2 += wab * load4(u2 + at);
    }
  const v4d wz = {b.w[2][0][i], b.w[2][1][i], b.w[2][2][i], b.w[2][3][i]};
  const v4d t0 = sum0 * wz, t1 = sum1 * wz, t2 = sum2 * wz;
  return Vec3((t0[0] + t0[1]) + (t0[2] + t0[3]), (t1[0] + t1[1]) + (t1[2] + t1[3]), (t2[0] + t2[1]) + (t2[2] + t2[3]));
}

// Adds one node's force through its stencil.
void spread_one(const KernelStencil& s, const Vec3& force, double* const f[3], int ny, int nz) {
  // The component pointers and the force in locals: read through f[d] and the reference
  // they were reloaded after every store (the spreading 7-8 % dearer on the bench case; a
  // double of the force field might alias the force).
  double* const f0 = f[0];
  double* const f1 = f[1];
  double* const f2 = f[2];
  const double fx = force[0], fy = force[1], fz = force[2];
  if (contiguous_z4(s)) {
    const v4d wz = {s.wz[0], s.wz[1], s.wz[2], s.wz[3]};
    const v4d fz0 = wz * fx, fz1 = wz * fy, fz2 = wz * fz;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const double wab = s.wx[a] * s.wy[b];
        if (wab == 0.0) continue;
        const std::size_t at = lattice_index(s.x[a], s.y[b], s.z[0], ny, nz);
        store4(f0 + at, load4(f0 + at) + wab * fz0);
        store4(f1 + at, load4(f1 + at) + wab * fz1);
        store4(f2 + at, load4(f2 + at) + wab * fz2);
      }
    return;
  }
  if (nz >= 8) switch (seam_tail(s, nz)) {
      case 1: return spread_row_ends<1>(stencil_rows(s, ny, nz), stencil_wz(s), force, f, nz);
      case 2: return spread_row_ends<2>(stencil_rows(s, ny, nz), stencil_wz(s), force, f, nz);
      case 3: return spread_row_ends<3>(stencil_rows(s, ny, nz), stencil_wz(s), force, f, nz);
      default: break;
    }
  for_each_stencil_node(s, ny, nz, [&](std::size_t node, double w) {
    f0[node] += w * fx;
    f1[node] += w * fy;
    f2[node] += w * fz;
  });
}

}  // namespace

void spread_forces(const NodeOrder& order, FluidLattice& fluid) {
  const int ny = fluid.ny(), nz = fluid.nz();
  double* const f[3] = {fluid.force(0), fluid.force(1), fluid.force(2)};
  // A node's stencil reaches at most support - 1 + drift_columns columns past its slab and
  // drift_columns before it, so the slabs of one phase can spread concurrently
  // (slab_schedule). Within a slab the nodes keep their order,
  // so the sums do not depend on the thread count.
  const int nx = fluid.nx();
  auto spread_slab = [&](int slab) {
    const std::size_t begin = order.slab_start[slab], end = order.slab_start[slab + 1];
    if (order.kernel != KernelKind::Peskin4) {
      for (std::size_t g = begin; g < end; ++g) spread_one(order.stencil_of(g), order.force[g], f, ny, nz);
      return;
    }
    // The stencils several at a time (peskin4_block), the nodes still in order.
    Peskin4Block block;
    for (std::size_t g0 = begin; g0 < end; g0 += kBlock) {
      const int n = static_cast<int>(std::min<std::size_t>(kBlock, end - g0));
      peskin4_block(order.position.data() + g0, n, nx, nz, block);
      for (int i = 0; i < n;) {
        if (!on_fast_path(block, i, nx, ny, nz)) {
          const Vec3& force = order.force[g0 + i];
          switch (on_seam_path(block, i, nx, ny, nz)) {
            case 1: spread_row_ends<1>(block_rows(block, i, nx, ny, nz), block_wz(block, i), force, f, nz); break;
            case 2: spread_row_ends<2>(block_rows(block, i, nx, ny, nz), block_wz(block, i), force, f, nz); break;
            case 3: spread_row_ends<3>(block_rows(block, i, nx, ny, nz), block_wz(block, i), force, f, nz); break;
            default: spread_one(edge_stencil(block, i, order, g0 + i), force, f, ny, nz);
          }
          ++i;
          continue;
        }
        const int run = run_length(block, i, n);
        const Vec3* const force = order.force.data() + g0 + i;
        if (run == 1) spread_rows<1>(block, i, force, f, nx, ny, nz);
        else if (run == 2) spread_rows<2>(block, i, force, f, nx, ny, nz);
        else spread_rows<3>(block, i, force, f, nx, ny, nz);
        i += run;
      }
    }
  };
  const SlabSchedule plan = slab_schedule(fluid.nx());
  for (const std::vector<int>& phase : plan.phase) {
    const long count = static_cast<long>(phase.size());
#pragma omp parallel for schedule(dynamic)
    for (long i = 0; i < count; ++i) spread_slab(phase[i]);
  }
  for (const int slab : plan.tail) spread_slab(slab);
}

void spread_forces(KernelKind kernel, const std::vector<std::vector<Vec3>>& positions,
                   const std::vector<std::vector<Vec3>>& forces, FluidLattice& fluid) {
  NodeOrder order;
  order_nodes(kernel, positions, forces, fluid.nx(), fluid.ny(), fluid.nz(), order);
  spread_forces(order, fluid);
}

void spread_forces(KernelKind kernel, const std::vector<Vec3>& positions, const std::vector<Vec3>& forces,
                   FluidLattice& fluid) {
  spread_forces(kernel, std::vector<std::vector<Vec3>>{positions}, std::vector<std::vector<Vec3>>{forces}, fluid);
}

Vec3 interpolate_field(const KernelStencil& s, const double* const u[3], int ny, int nz) {
  if (contiguous_z4(s)) {
    v4d sum[3] = {};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const double wab = s.wx[a] * s.wy[b];
        if (wab == 0.0) continue;
        const std::size_t at = lattice_index(s.x[a], s.y[b], s.z[0], ny, nz);
        for (int d = 0; d < 3; ++d) sum[d] += wab * load4(u[d] + at);
      }
    const v4d wz = {s.wz[0], s.wz[1], s.wz[2], s.wz[3]};
    Vec3 out;
    for (int d = 0; d < 3; ++d) {
      const v4d t = sum[d] * wz;
      out[d] = (t[0] + t[1]) + (t[2] + t[3]);
    }
    return out;
  }
  if (nz >= 4) switch (seam_tail(s, nz)) {
      case 1: return interpolate_row_ends<1>(stencil_rows(s, ny, nz), stencil_wz(s), u, nz);
      case 2: return interpolate_row_ends<2>(stencil_rows(s, ny, nz), stencil_wz(s), u, nz);
      case 3: return interpolate_row_ends<3>(stencil_rows(s, ny, nz), stencil_wz(s), u, nz);
      default: break;
    }
  return interpolate(s, [&](int i, int j, int k) {
    const std::size_t n = lattice_index(i, j, k, ny, nz);
    return Vec3(u[0][n], u[1][n], u[2][n]);
  });
}

void interpolate_sorted(const NodeOrder& order, std::size_t begin, std::size_t end, const double* const u[3],
                        Vec3* out) {
  const int nx = order.nx, ny = order.ny, nz = order.nz;
  if (order.kernel != KernelKind::Peskin4) {
    for (std::size_t g = begin; g < end; ++g) out[g - begin] = interpolate_field(order.stencil_of(g), u, ny, nz);
    return;
  }
  Peskin4Block block;
  for (std::size_t g0 = begin; g0 < end; g0 += kBlock) {
    const int n = static_cast<int>(std::min<std::size_t>(kBlock, end - g0));
    peskin4_block(order.position.data() + g0, n, nx, nz, block);
    for (int i = 0; i < n; ++i) {
      Vec3& at = out[g0 + i - begin];
      if (on_fast_path(block, i, nx, ny, nz)) {
        at = interpolate_rows(block, i, u, nx, ny, nz);
        continue;
      }
      switch (on_seam_path(block, i, nx, ny, nz)) {
        case 1: at = interpolate_row_ends<1>(block_rows(block, i, nx, ny, nz), block_wz(block, i), u, nz); break;
        case 2: at = interpolate_row_ends<2>(block_rows(block, i, nx, ny, nz), block_wz(block, i), u, nz); break;
        case 3: at = interpolate_row_ends<3>(block_rows(block, i, nx, ny, nz), block_wz(block, i), u, nz); break;
        default: at = interpolate_field(edge_stencil(block, i, order, g0 + i), u, ny, nz);
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
