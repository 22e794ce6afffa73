#include "solver/coupling/node_order.hpp"

#include <algorithm>
#include <stdexcept>

namespace rbcal::solver {

void sort_nodes(KernelKind kernel, const std::vector<std::vector<Vec3>>& positions, int nx, int ny, int nz,
                NodeOrder& order) {
  // Sorted by the lattice index (x * ny + y) * nz + z of the stencil's first node; stable,
  // so the order (and every sum that follows it) does not depend on the thread count.
  // The modulo only where a support starts outside the box (an integer division per
  // coordinate was a fifth of this function's time).
  if (nx > INT16_MAX || ny > INT16_MAX || nz > INT16_MAX)  // KernelStencil's indices
    throw std::invalid_argument("immersed boundary: lattice wider than 32767 nodes");
  auto in_box = [](int i, int n) { return i >= 0 && i < n ? i : wrap_index(i, n); };
  auto key_of = [&](const Vec3& p) {
    const int x = in_box(support_start(kernel, p.x()), nx);
    const int y = std::clamp(support_start(kernel, p.y()), 0, ny - 1);
    const int z = in_box(support_start(kernel, p.z()), nz);
    return lattice_index(x, y, z, ny, nz);
  };
  const std::size_t keys = static_cast<std::size_t>(nx) * ny * nz;
  // The keys in mesh order, then the sort, which is serial; the permutation after it runs
  // in parallel (the serial version, which also copied positions and forces into place,
  // was a third of a step's waiting). The (cell, node) pair of each place in mesh
  // order depends only on the cells' sizes: rebuilt when they change.
  auto& first = order.cell_first;
  bool same_cells = first.size() == positions.size() + 1;
  for (std::size_t c = 0; same_cells && c < positions.size(); ++c)
    same_cells = first[c + 1] - first[c] == positions[c].size();
  if (!same_cells) {
    first.assign(positions.size() + 1, 0);
    for (std::size_t c = 0; c < positions.size(); ++c) first[c + 1] = first[c] + positions[c].size();
    order.mesh_order.resize(first.back());
    for (std::size_t c = 0; c < positions.size(); ++c)
      for (std::size_t n = 0; n < positions[c].size(); ++n)
        order.mesh_order[first[c] + n] = {static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(n)};
  }
  const std::size_t total = first.back();
  auto& key = order.key;
  key.resize(total);
  const long cells = static_cast<long>(positions.size());
#pragma omp parallel for schedule(static)
  for (long c = 0; c < cells; ++c) {
    std::uint32_t* k = key.data() + first[c];
    for (const Vec3& p : positions[c]) *k++ = static_cast<std::uint32_t>(key_of(p));
  }
  const std::vector<std::uint64_t>& sorted = order.sort(key, keys);
  const int slabs = NodeOrder::slab_count(nx);
  order.slab_start.resize(slabs + 1);
  for (int s = 0; s <= slabs; ++s) {
    const std::size_t bound = std::min(keys, static_cast<std::size_t>(s) * NodeOrder::slab_width * ny * nz);
    order.slab_start[s] = static_cast<std::size_t>(
        std::partition_point(sorted.begin(), sorted.end(),
                             [&](std::uint64_t r) { return key_of_record(r) < bound; }) -
        sorted.begin());
  }
  order.nodes.resize(total);
  order.sorted_place.resize(total);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < static_cast<long>(total); ++i) {
    const std::size_t in_mesh_order = index_of_record(sorted[i]);
    order.nodes[i] = order.mesh_order[in_mesh_order];
    order.sorted_place[in_mesh_order] = static_cast<std::uint32_t>(i);
  }
  order.kernel = kernel;
  order.nx = nx;
  order.ny = ny;
  order.nz = nz;
}

void gather_nodes(const std::vector<std::vector<Vec3>>& positions, const std::vector<std::vector<Vec3>>& forces,
                  NodeOrder& order) {
  const std::size_t total = order.nodes.size();
  const auto& first = order.cell_first;
  bool same_cells = first.size() == positions.size() + 1 && first.back() == total;
  for (std::size_t c = 0; same_cells && c < positions.size(); ++c)
    same_cells = first[c + 1] - first[c] == positions[c].size() && forces[c].size() == positions[c].size();
  if (!same_cells) throw std::logic_error("gather_nodes: the cells are not those sorted");
  order.position.resize(total);
  order.force.resize(total);
  const long count = static_cast<long>(total);
  constexpr long gather_ahead = 8;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < count; ++i) {
    // The copies gather from all over the meshes: fetching a few nodes ahead hides the
    // misses (the ordering 17 % cheaper on the bench case, docs/performance.md).
    if (i + gather_ahead < count) {
      const auto [ahead_cell, ahead_node] = order.nodes[i + gather_ahead];
      __builtin_prefetch(&positions[ahead_cell][ahead_node], 0, 3);
      __builtin_prefetch(&forces[ahead_cell][ahead_node], 0, 3);
    }
    const auto [c, n] = order.nodes[i];
    order.position[i] = positions[c][n];
    order.force[i] = forces[c][n];
  }
}

void order_nodes(KernelKind kernel, const std::vector<std::vector<Vec3>>& positions,
                 const std::vector<std::vector<Vec3>>& forces, int nx, int ny, int nz, NodeOrder& order) {
  sort_nodes(kernel, positions, nx, ny, nz, order);
  gather_nodes(positions, forces, order);
}

SlabSchedule slab_schedule(int nx) {
  const int width = NodeOrder::slab_width;
  const int slabs = NodeOrder::slab_count(nx);
  // Slab s holds the stencils that started in its columns when sorted; they may since have
  // moved drift_columns either way, and each reaches support - 1 columns past its start.
  const int left = NodeOrder::drift_columns, right = kernel_support(KernelKind::Peskin4) - 1 + NodeOrder::drift_columns;
  static_assert(NodeOrder::slab_width * (NodeOrder::slab_phases - 1) >
                    kernel_support(KernelKind::Peskin4) - 2 + 2 * NodeOrder::drift_columns,
                "slabs of one phase away from the wrap would share columns");
  SlabSchedule plan;
  std::vector<std::vector<int>> writer(NodeOrder::slab_phases, std::vector<int>(nx, -1));
  for (int s = 0; s < slabs; ++s) {
    const int first = width * s - left, last = std::min(width * s + width - 1, nx - 1) + right;
    // Columns of the same phase already taken (a slab wider than the box meets itself).
    std::vector<int>& taken = writer[s % NodeOrder::slab_phases];
    bool meets = last - first + 1 > nx;
    for (int c = first; c <= last && !meets; ++c) meets = taken[wrap_index(c, nx)] != -1;
    if (meets) {
      plan.tail.push_back(s);
      continue;
    }
    for (int c = first; c <= last; ++c) taken[wrap_index(c, nx)] = s;
    plan.phase[s % NodeOrder::slab_phases].push_back(s);
  }
  return plan;
}

}  // namespace rbcal::solver
