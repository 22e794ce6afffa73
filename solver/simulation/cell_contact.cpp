#include "solver/simulation/cell_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rbcal::solver {

namespace {

// Nodes binned into cubes of side >= range: a node's partners lie in its own bin and the
// 26 around it (periodic in x and z).
struct NodeBins {
  int bx = 1, by = 1, bz = 1;
  double side_x = 1.0, side_y = 1.0, side_z = 1.0, y_low = 0.0;
  std::vector<std::uint32_t> start;                  // bin b holds entries [start[b], start[b + 1])
  std::vector<std::pair<std::uint32_t, std::uint32_t>> entries;  // (cell, node)
  std::vector<Vec3> wrapped;                         // entry positions, wrapped into the box in x, z

  int bin_x(double v) const { return std::min(bx - 1, static_cast<int>(v / side_x)); }
  int bin_y(double v) const { return std::clamp(static_cast<int>((v - y_low) / side_y), 0, by - 1); }
  int bin_z(double v) const { return std::min(bz - 1, static_cast<int>(v / side_z)); }
  int index(int ix, int iy, int iz) const { return (ix * by + iy) * bz + iz; }
};

double wrap(double v, double period) {
  const double w = v - period * std::floor(v / period);
  return w >= period ? 0.0 : w;
}

NodeBins bin_nodes(const std::vector<std::vector<Vec3>>& x, double range, double period_x, double period_z) {
  NodeBins b;
  double y_low = 1e300, y_high = -1e300;
  for (const auto& cell : x)
    for (const Vec3& p : cell) y_low = std::min(y_low, p.y()), y_high = std::max(y_high, p.y());
  // At least three bins per periodic direction, so that the 27 neighbours are distinct.
  b.bx = std::max(3, static_cast<int>(period_x / range));
  b.bz = std::max(3, static_cast<int>(period_z / range));
  b.by = std::max(1, static_cast<int>((y_high - y_low) / range));
  b.side_x = period_x / b.bx;
  b.side_z = period_z / b.bz;
  b.side_y = std::max(range, (y_high - y_low) / b.by);
  b.y_low = y_low;
  const std::size_t bins = static_cast<std::size_t>(b.bx) * b.by * b.bz;
  std::vector<std::uint32_t> count(bins + 1, 0);
  std::vector<std::uint32_t> bin_of;
  std::vector<Vec3> wrapped;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ids;
  for (std::uint32_t i = 0; i < x.size(); ++i)
    for (std::uint32_t m = 0; m < x[i].size(); ++m) {
      const Vec3 p(wrap(x[i][m].x(), period_x), x[i][m].y(), wrap(x[i][m].z(), period_z));
      const auto k = static_cast<std::uint32_t>(b.index(b.bin_x(p.x()), b.bin_y(p.y()), b.bin_z(p.z())));
      bin_of.push_back(k);
      wrapped.push_back(p);
      ids.emplace_back(i, m);
      ++count[k + 1];
    }
  for (std::size_t k = 0; k < bins; ++k) count[k + 1] += count[k];
  b.start = count;
  b.entries.resize(ids.size());
  b.wrapped.resize(ids.size());
  for (std::size_t e = 0; e < ids.size(); ++e) {
    const std::uint32_t slot = count[bin_of[e]]++;
    b.entries[slot] = ids[e];
    b.wrapped[slot] = wrapped[e];
  }
  return b;
}

}  // namespace

ContactCount add_contact_forces(const std::vector<std::vector<Vec3>>& x, double range, double strength,
                                double period_x, double period_z, std::vector<std::vector<Vec3>>& f) {
  ContactCount count;
  if (!(range > 0.0) || !(strength > 0.0) || x.empty()) return count;
  const NodeBins b = bin_nodes(x, range, period_x, period_z);
  const double floor = 0.2 * range, range2 = range * range;
  const long entries = static_cast<long>(b.entries.size());
  long pairs = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : pairs)
  for (long e = 0; e < entries; ++e) {
    const auto [cell, node] = b.entries[e];
    const Vec3& p = b.wrapped[e];
    const int ix = b.bin_x(p.x()), iy = b.bin_y(p.y()), iz = b.bin_z(p.z());
    Vec3 force = Vec3::Zero();
    for (int dx = -1; dx <= 1; ++dx) {
      // A neighbour bin across the seam holds positions one period away.
      const int jx = ix + dx;
      const double shift_x = jx < 0 ? -period_x : (jx >= b.bx ? period_x : 0.0);
      for (int dy = -1; dy <= 1; ++dy) {
        const int jy = iy + dy;
        if (jy < 0 || jy >= b.by) continue;
        for (int dz = -1; dz <= 1; ++dz) {
          const int jz = iz + dz;
          const double shift_z = jz < 0 ? -period_z : (jz >= b.bz ? period_z : 0.0);
          const Vec3 q = p - Vec3(shift_x, 0.0, shift_z);  // p relative to the bin's own image
          const int k = b.index((jx + b.bx) % b.bx, jy, (jz + b.bz) % b.bz);
          for (std::uint32_t o = b.start[k]; o < b.start[k + 1]; ++o) {
            const Vec3 d = q - b.wrapped[o];
            const double r2 = d.squaredNorm();
            if (r2 >= range2 || b.entries[o].first == cell) continue;
            const double r = std::sqrt(r2);
            force += (strength * (range / std::max(r, floor) - 1.0) / std::max(r, 1e-12)) * d;
            ++pairs;
          }
        }
      }
    }
    f[cell][node] += force;
  }
  count.node_pairs = pairs;
  return count;
}

}  // namespace rbcal::solver
