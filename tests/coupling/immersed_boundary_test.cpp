// Immersed-boundary kernels and transfer operators (Peskin, Acta Numerica 11 (2002) 479):
// moment conditions of the kernels, conservation of force and torque by spreading, and
// exact interpolation of linear velocity fields.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <stdexcept>
#include <utility>

#include "solver/coupling/immersed_boundary.hpp"

using namespace rbcal::solver;

class Kernels : public ::testing::TestWithParam<KernelKind> {};

TEST_P(Kernels, SatisfyZerothAndFirstMomentConditions) {
  const KernelKind k = GetParam();
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double r = u(rng);
    double m0 = 0.0, m1 = 0.0, m2 = 0.0, even = 0.0;
    for (int j = -6; j <= 6; ++j) {
      const double w = kernel_weight(k, r - j);
      EXPECT_GE(w, 0.0);
      m0 += w;
      m1 += (r - j) * w;
      m2 += w * w;
      if (j % 2 == 0) even += w;
    }
    EXPECT_NEAR(m0, 1.0, 1e-14) << r;
    EXPECT_NEAR(m1, 0.0, 1e-14) << r;
    if (k == KernelKind::Peskin4) {
      EXPECT_NEAR(m2, 3.0 / 8.0, 1e-14) << r;  // Peskin (2002) eq. 6.25
      EXPECT_NEAR(even, 0.5, 1e-14) << r;
    }
  }
  EXPECT_EQ(kernel_weight(k, kernel_support(k) / 2.0 + 1e-9), 0.0);
}

INSTANTIATE_TEST_SUITE_P(All, Kernels, ::testing::Values(KernelKind::Linear2, KernelKind::Roma3, KernelKind::Peskin4));

TEST(Spreading, ConservesForceAndTorque) {
  for (KernelKind k : {KernelKind::Linear2, KernelKind::Roma3, KernelKind::Peskin4}) {
    FluidConfig cfg;
    cfg.nx = 16;
    cfg.ny = 16;
    cfg.nz = 16;
    FluidLattice fluid(cfg);
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> pos(4.0, 11.0), frc(-1.0, 1.0);
    std::vector<Vec3> x, f;
    for (int i = 0; i < 50; ++i) {
      x.emplace_back(pos(rng), pos(rng), pos(rng));
      f.emplace_back(frc(rng), frc(rng), frc(rng));
    }
    spread_forces(k, x, f, fluid);
    Vec3 total = Vec3::Zero(), torque = Vec3::Zero(), total_l = Vec3::Zero(), torque_l = Vec3::Zero();
    for (std::size_t i = 0; i < x.size(); ++i) {
      total += f[i];
      torque += x[i].cross(f[i]);
    }
    for (int ix = 0; ix < 16; ++ix)
      for (int iy = 0; iy < 16; ++iy)
        for (int iz = 0; iz < 16; ++iz) {
          const std::size_t n = fluid.index(ix, iy, iz);
          const Vec3 fn(fluid.force(0)[n], fluid.force(1)[n], fluid.force(2)[n]);
          total_l += fn;
          torque_l += Vec3(ix, iy, iz).cross(fn);
        }
    EXPECT_LT((total_l - total).norm(), 1e-12);
    EXPECT_LT((torque_l - torque).norm(), 1e-11);
  }
}

TEST(Spreading, ConservesForceNextToAWall) {
  FluidConfig cfg;
  cfg.nx = cfg.ny = cfg.nz = 8;
  FluidLattice fluid(cfg);
  spread_forces(KernelKind::Peskin4, {Vec3(3.3, 0.2, 4.1)}, {Vec3(0.3, -1.0, 2.0)}, fluid);
  Vec3 total = Vec3::Zero();
  for (std::size_t n = 0; n < fluid.node_count(); ++n) total += Vec3(fluid.force(0)[n], fluid.force(1)[n], fluid.force(2)[n]);
  EXPECT_LT((total - Vec3(0.3, -1.0, 2.0)).norm(), 1e-14);
}

TEST(Interpolation, ReproducesLinearFieldsExactly) {
  FluidConfig cfg;
  cfg.nx = cfg.ny = cfg.nz = 16;
  FluidLattice fluid(cfg);
  Eigen::Matrix3d grad;
  grad << 1e-3, -2e-4, 5e-4, 3e-4, -1e-3, 2e-4, -4e-4, 1e-4, 7e-4;
  const Vec3 u0(1e-3, -2e-3, 3e-3);
  for (int ix = 0; ix < 16; ++ix)
    for (int iy = 0; iy < 16; ++iy)
      for (int iz = 0; iz < 16; ++iz) {
        const Vec3 u = u0 + grad * Vec3(ix, iy, iz);
        fluid.set_equilibrium(fluid.index(ix, iy, iz), 1.0, u.x(), u.y(), u.z());
      }
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> pos(3.0, 12.0);
  for (KernelKind k : {KernelKind::Linear2, KernelKind::Roma3, KernelKind::Peskin4})
    for (int i = 0; i < 100; ++i) {
      const Vec3 x(pos(rng), pos(rng), pos(rng));
      EXPECT_LT((interpolate_velocity(k, fluid, x) - (u0 + grad * x)).norm(), 1e-15);
    }
}

// make_stencil computes the 2- and 4-point weights in closed form from the fractional
// position; they must equal the kernel evaluated at each node's distance.
TEST(Stencil, WeightsEqualTheKernelAtEachNode) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> pos(3.0, 12.0);
  for (KernelKind k : {KernelKind::Linear2, KernelKind::Roma3, KernelKind::Peskin4}) {
    for (int trial = 0; trial < 500; ++trial) {
      const Vec3 p(pos(rng), pos(rng), pos(rng));
      const KernelStencil s = make_stencil(k, p, 16, 16, 16);
      double sum = 0.0;
      for (int i = 0; i < s.count; ++i) {
        EXPECT_NEAR(s.wx[i], kernel_weight(k, p.x() - s.x[i]), 1e-15) << p.transpose();
        EXPECT_NEAR(s.wy[i], kernel_weight(k, p.y() - s.y[i]), 1e-15) << p.transpose();
        EXPECT_NEAR(s.wz[i], kernel_weight(k, p.z() - s.z[i]), 1e-15) << p.transpose();
        sum += s.wx[i];
      }
      // The support covers every node the kernel reaches: the weights sum to one.
      EXPECT_NEAR(sum, 1.0, 1e-14);
    }
  }
}

// The slabs of one parallel phase never write a common lattice column, for every lattice
// width: each slab's columns are those its nodes' stencils (the widest support, starting
// anywhere in the slab or up to drift_columns beyond it either way, as nodes may have
// moved since they were sorted) can reach, wrapped periodically. Slab counts whose last
// slab is narrow once let the slab before the last wrap onto slab 0 in the same phase.
// Most slabs run in the parallel phases, not in the serial tail.
TEST(Spreading, SlabsOfOnePhaseNeverShareAColumn) {
  const int width = NodeOrder::slab_width, support = kernel_support(KernelKind::Peskin4);
  const int drift = NodeOrder::drift_columns;
  for (int nx = 1; nx <= 200; ++nx) {
    const SlabSchedule plan = slab_schedule(nx);
    const int slabs = (nx + width - 1) / width;
    std::vector<int> seen(slabs, 0);
    for (int s : plan.tail) ++seen[s];
    for (const std::vector<int>& phase : plan.phase)
      for (int s : phase) ++seen[s];
    for (int s = 0; s < slabs; ++s) EXPECT_EQ(seen[s], 1) << "nx " << nx << " slab " << s;
    for (const std::vector<int>& phase : plan.phase) {
      std::vector<int> writer(nx, -1);
      for (int s : phase)
        for (int start = width * s - drift; start < std::min(width * (s + 1), nx) + drift; ++start)
          for (int k = 0; k < support; ++k) {
            int& w = writer[wrap_index(start + k, nx)];
            EXPECT_TRUE(w == -1 || w == s) << "nx " << nx << ": slabs " << w << " and " << s << " write column "
                                           << wrap_index(start + k, nx) << " in one phase";
            w = s;
          }
    }
    if (slabs >= 4) {
      EXPECT_LE(plan.tail.size(), 2u) << "nx " << nx;
    }
  }
}

// Spreading many cells at once runs slabs of x in parallel; the field must equal a plain
// node-by-node sum, also for slab counts that are odd (nx = 9, 11, 21: three or six slabs,
// the last one narrow), with a narrow last slab (nx = 14), a single slab (nx = 4), with nodes
// across the periodic boundary, with runs of nodes that share their stencil's first node, and
// with nodes that have moved up to NodeOrder::max_drift in each direction since they were
// sorted (spread from where they are now).
namespace {

void expect_slabs_equal_a_serial_sum(double drift) {
  for (int nx : {4, 9, 11, 14, 16, 21}) {
    FluidConfig cfg;
    cfg.nx = nx;
    cfg.ny = 12;
    cfg.nz = 6;
    FluidLattice fluid(cfg);
    std::mt19937_64 rng(static_cast<unsigned>(nx));
    std::uniform_real_distribution<double> px(-3.0, nx + 3.0), py(2.0, 9.0), pz(-2.0, 8.0), frc(-1.0, 1.0),
        move(-drift, drift);
    std::vector<std::vector<Vec3>> sorted_at(5), x(5), f(5);
    const Vec3 nudge(0.01, 0.02, 0.03);
    for (int c = 0; c < 5; ++c)
      for (int i = 0; i < 200; ++i) {
        f[c].emplace_back(frc(rng), frc(rng), frc(rng));
        if (i % 5 == 4) {
          // Every fifth node next to the one before: runs of nodes sharing their stencil's
          // first node, which the spreading takes together.
          sorted_at[c].push_back(sorted_at[c].back() + nudge);
          x[c].push_back(x[c].back() + nudge);
          continue;
        }
        sorted_at[c].emplace_back(px(rng), py(rng), pz(rng));
        // Every fourth node moved by the whole drift along x, where it matters most.
        const double dx = i % 4 == 0 ? (i % 8 == 0 ? drift : -drift) : move(rng);
        x[c].push_back(sorted_at[c].back() + Vec3(dx, move(rng), move(rng)));
      }
    NodeOrder order;
    sort_nodes(KernelKind::Peskin4, sorted_at, cfg.nx, cfg.ny, cfg.nz, order);
    gather_nodes(x, f, order);
    spread_forces(order, fluid);
    std::vector<double> expected(3 * fluid.node_count(), 0.0);
    for (int c = 0; c < 5; ++c)
      for (int i = 0; i < 200; ++i) {
        const KernelStencil s = make_stencil(KernelKind::Peskin4, x[c][i], cfg.nx, cfg.ny, cfg.nz);
        for (int a = 0; a < 4; ++a)
          for (int b = 0; b < 4; ++b)
            for (int d = 0; d < 4; ++d)
              for (int k = 0; k < 3; ++k)
                expected[3 * fluid.index(s.x[a], s.y[b], s.z[d]) + k] += s.wx[a] * s.wy[b] * s.wz[d] * f[c][i][k];
      }
    for (std::size_t n = 0; n < fluid.node_count(); ++n)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(fluid.force(k)[n], expected[3 * n + k], 1e-12) << "nx " << nx << " node " << n << " drift " << drift;
  }
}

}  // namespace

TEST(Spreading, ParallelSlabsEqualASerialSum) { expect_slabs_equal_a_serial_sum(0.0); }

TEST(Spreading, ParallelSlabsEqualASerialSumAfterTheNodesHaveMoved) {
  expect_slabs_equal_a_serial_sum(NodeOrder::max_drift);
}

TEST(NodeOrder, SortsStablyByTheSupportStartOnSmallAndLargeLattices) {
  // 300 nodes on 12^3 nodes (a counting sort) and on 64 x 48 x 80 (a radix sort): the nodes
  // in the order of their stencil's first lattice node, ties in (cell, node) order, the
  // slabs' starts where the keys cross a slab, and the copies those of the nodes named. One
  // order serves both, the cells' sizes changing between them (its (cell, node) pairs are
  // kept while the sizes stay).
  NodeOrder order;
  for (const auto& [nx, ny, nz] : {std::array{12, 12, 12}, std::array{64, 48, 80}}) {
    std::mt19937_64 rng(static_cast<unsigned>(nx));
    std::uniform_real_distribution<double> px(-2.0, nx + 2.0), py(0.0, ny - 1.0), pz(-2.0, nz + 2.0), frc(-1.0, 1.0);
    std::vector<std::vector<Vec3>> x(3), f(3);
    const int nodes_in[3] = {100, nx == 12 ? 100 : 70, nx == 12 ? 100 : 130};
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < nodes_in[c]; ++i) {
        // Every fifth node shares its predecessor's support: ties to keep in order.
        x[c].push_back(i % 5 == 4 ? x[c].back() + Vec3(0.01, 0.0, 0.0) : Vec3(px(rng), py(rng), pz(rng)));
        f[c].emplace_back(frc(rng), frc(rng), frc(rng));
      }
    order_nodes(KernelKind::Peskin4, x, f, nx, ny, nz, order);
    auto key_of = [&](const Vec3& p) {
      const KernelStencil s = make_stencil(KernelKind::Peskin4, p, nx, ny, nz);
      const int y = std::clamp(support_start(KernelKind::Peskin4, p.y()), 0, ny - 1);
      return lattice_index(s.x[0], y, s.z[0], ny, nz);
    };
    ASSERT_EQ(order.nodes.size(), 300u);
    for (std::size_t i = 0; i < order.nodes.size(); ++i) {
      const auto [c, n] = order.nodes[i];
      EXPECT_EQ(order.position[i], x[c][n]);
      EXPECT_EQ(order.force[i], f[c][n]);
      EXPECT_EQ(order.stencil_of(i).wz, make_stencil(KernelKind::Peskin4, x[c][n], nx, ny, nz).wz);
      if (i == 0) continue;
      const auto [pc, pn] = order.nodes[i - 1];
      const std::size_t k = key_of(x[c][n]), pk = key_of(x[pc][pn]);
      ASSERT_LE(pk, k) << "position " << i;
      if (pk == k) {
        EXPECT_LT(std::pair(pc, pn), std::pair(c, n)) << "a tie out of order at " << i;
      }
    }
    for (int s = 0; s <= NodeOrder::slab_count(nx); ++s) {
      const std::size_t bound = std::min<std::size_t>(static_cast<std::size_t>(s) * NodeOrder::slab_width * ny * nz,
                                                      static_cast<std::size_t>(nx) * ny * nz);
      std::size_t expected = 0;
      while (expected < order.nodes.size() &&
             key_of(x[order.nodes[expected].first][order.nodes[expected].second]) < bound)
        ++expected;
      EXPECT_EQ(order.slab_start[s], expected) << "slab " << s;
    }
  }
}

// The interpolation at sorted nodes computes their 4-point stencils several at a time, with
// a plain path for supports of whole z rows away from the walls; it must give each node what
// its own stencil gives, also next to the walls (weights renormalised), across the periodic x
// and z boundaries, for nodes several boxes away in x and z (a run's positions are unwrapped:
// shear carries cells out of the box), supports starting exactly on a multiple of the box
// (the wrap's division is exact there), and for a last block shorter than the others.
// Rows of 12 and 8 nodes (a seam support's two row ends apart and adjacent) and of 6 (they
// overlap).
static void expect_sorted_interpolation_equals_own_stencils(int nz) {
  SCOPED_TRACE("nz " + std::to_string(nz));
  const int nx = 20, ny = 16;
  const std::size_t nodes = static_cast<std::size_t>(nx) * ny * nz;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::vector<double> field(3 * nodes);
  for (double& v : field) v = value(rng);
  const double* const u[3] = {field.data(), field.data() + nodes, field.data() + 2 * nodes};
  std::uniform_real_distribution<double> px(-3.0, nx + 3.0), py(0.0, ny - 1.0), pz(-3.0, nz + 3.0);
  std::uniform_int_distribution<int> boxes(-5, 5);
  std::vector<std::vector<Vec3>> x(3), f(3);
  for (int c = 0; c < 2; ++c)
    for (int i = 0; i < 333; ++i) {
      x[c].emplace_back(px(rng), py(rng), pz(rng));
      // Every third node of the second cell several boxes away in x and z.
      if (c == 1 && i % 3 == 0) x[c].back() += Vec3(boxes(rng) * nx, 0.0, boxes(rng) * nz);
      f[c].emplace_back(0.0, 0.0, 0.0);
    }
  // Supports starting on k nx and k nz (the first node one below the node's floor).
  for (int k = -4; k <= 4; ++k) {
    x[2].emplace_back(k * nx + 1.25, py(rng), k * nz + 1.75);
    f[2].emplace_back(0.0, 0.0, 0.0);
  }
  // Nodes beyond 2^20 lattice spacings in x or z, which the blocks hand to make_stencil.
  for (const Vec3& p : {Vec3(3.0e6 + 0.3, 4.2, 2.5), Vec3(0.4, 7.7, -2.5e6 - 0.6)}) {
    x[2].push_back(p);
    f[2].emplace_back(0.0, 0.0, 0.0);
  }
  NodeOrder order;
  order_nodes(KernelKind::Peskin4, x, f, nx, ny, nz, order);
  const std::size_t total = order.nodes.size();
  std::vector<Vec3> sampled(total);
  interpolate_sorted(order, 0, total, u, sampled.data());
  int walls = 0, wraps = 0, away = 0, far = 0;
  for (std::size_t g = 0; g < total; ++g) {
    const KernelStencil s = make_stencil(KernelKind::Peskin4, order.position[g], nx, ny, nz);
    const Vec3 expected = interpolate(s, [&](int i, int j, int k) {
      const std::size_t n = lattice_index(i, j, k, ny, nz);
      return Vec3(u[0][n], u[1][n], u[2][n]);
    });
    EXPECT_NEAR((sampled[g] - expected).norm(), 0.0, 1e-14) << "node " << g;
    // And to the last bit what the single node's own path gives.
    EXPECT_EQ(sampled[g], interpolate_field(s, u, ny, nz)) << "node " << g;
    walls += order.position[g].y() < 1.0 || order.position[g].y() >= ny - 2.0;
    wraps += s.x[3] != s.x[0] + 3 || s.z[3] != s.z[0] + 3;
    away += order.position[g].x() < -nx || order.position[g].x() >= 2 * nx;
    far += std::abs(order.position[g].x()) > 1048576.0 || std::abs(order.position[g].z()) > 1048576.0;
  }
  EXPECT_EQ(far, 2);
  // Both kinds of boundary were met, and nodes boxes away.
  EXPECT_GT(walls, 20);
  EXPECT_GT(wraps, 50);
  EXPECT_GT(away, 50);
}

TEST(Interpolation, AtSortedNodesEqualsEachNodesOwnStencil) {
  for (const int nz : {12, 8, 6}) expect_sorted_interpolation_equals_own_stencils(nz);
}

// A kept order serves only the cells it sorted: other cell sizes are refused.
TEST(NodeOrder, GatherRefusesCellsOfOtherSizes) {
  std::vector<std::vector<Vec3>> x = {{Vec3(2, 3, 4), Vec3(5, 6, 7)}, {Vec3(8, 6, 4)}};
  NodeOrder order;
  sort_nodes(KernelKind::Peskin4, x, 12, 12, 12, order);
  EXPECT_NO_THROW(gather_nodes(x, x, order));
  std::vector<std::vector<Vec3>> moved = {{Vec3(2, 3, 4)}, {Vec3(8, 6, 4), Vec3(5, 6, 7)}};
  EXPECT_THROW(gather_nodes(moved, moved, order), std::logic_error);
}

// The spreading of sorted nodes (stencils eight at a time, runs of nodes that share a first
// node taken together) adds, to the last bit, what each node alone adds through its own
// stencil (make_stencil), in the same order: slab by slab as the schedule runs them, node by
// node within a slab. Nodes on lattice coordinates (zero weights), in runs of four, across
// the periodic x and z boundaries, next to the walls (weights renormalised) and whole boxes
// away in x and z (unwrapped positions) included. Every support adds w_xy (w_z f) to each of
// its rows, one across the periodic z seam too (its rows read as the row's last four nodes
// and its first four).
// Rows of 12 and 8 nodes take the seam supports' two row ends; rows of 6, where they would
// overlap, the node-by-node sum (w_xy w_z) f.
static void expect_sorted_spreading_adds_what_each_node_adds(int nz) {
  SCOPED_TRACE("nz " + std::to_string(nz));
  const int nx = 24, ny = 16;
  FluidConfig cfg;
  cfg.nx = nx;
  cfg.ny = ny;
  cfg.nz = nz;
  FluidLattice fluid(cfg);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> px(0.0, nx), py(0.0, ny - 1.0), pz(0.0, nz), frc(-1.0, 1.0);
  std::uniform_int_distribution<int> boxes(-3, 3);
  std::vector<std::vector<Vec3>> x(3), f(3);
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 300; ++i) {
      f[c].emplace_back(frc(rng), frc(rng), frc(rng));
      if (i % 7 == 3) x[c].emplace_back(std::floor(px(rng)), std::floor(py(rng)), std::floor(pz(rng)));
      else if (i % 7 >= 4) x[c].push_back(x[c].back() + Vec3(0.01, 0.02, 0.03));  // a run
      else x[c].emplace_back(px(rng), py(rng), pz(rng));
      if (c == 2 && i % 7 < 3) x[c].back() += Vec3(boxes(rng) * nx, 0.0, boxes(rng) * nz);  // whole boxes away
    }
  NodeOrder order;
  order_nodes(KernelKind::Peskin4, x, f, nx, ny, nz, order);
  spread_forces(order, fluid);
  std::vector<double> expected(3 * fluid.node_count(), 0.0);
  int walls = 0, seams = 0;
  auto add_slab = [&](int slab) {
    for (std::size_t g = order.slab_start[slab]; g < order.slab_start[slab + 1]; ++g) {
      const KernelStencil st = make_stencil(KernelKind::Peskin4, order.position[g], nx, ny, nz);
      const bool rows = st.z[3] == st.z[0] + 3;
      walls += order.position[g].y() < 1.0 || order.position[g].y() >= ny - 2.0;  // a row beyond a wall
      seams += !rows;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          const double wab = st.wx[a] * st.wy[b];
          if (wab == 0.0) continue;  // beyond a wall
          for (int k = 0; k < 4; ++k)
            for (int d = 0; d < 3; ++d) {
              double& at = expected[d * fluid.node_count() + fluid.index(st.x[a], st.y[b], st.z[k])];
              at = rows || nz >= 8 ? at + wab * (st.wz[k] * order.force[g][d])
                                   : at + (wab * st.wz[k]) * order.force[g][d];
            }
        }
    }
  };
  const SlabSchedule plan = slab_schedule(nx);
  for (const std::vector<int>& phase : plan.phase)
    for (int slab : phase) add_slab(slab);
  for (int slab : plan.tail) add_slab(slab);
  std::size_t differing = 0;
  for (int d = 0; d < 3; ++d)
    for (std::size_t n = 0; n < fluid.node_count(); ++n) differing += fluid.force(d)[n] != expected[d * fluid.node_count() + n];
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(walls, 20);  // both kinds of edge were met
  EXPECT_GT(seams, 50);
}

TEST(Spreading, SortedNodesAddWhatEachNodeAddsAlone) {
  for (const int nz : {12, 8, 6}) expect_sorted_spreading_adds_what_each_node_adds(nz);
}
