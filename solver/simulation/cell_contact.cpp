#include "solver/simulation/cell_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace rbcal::solver {

int NodeBins::bin_x(double v) const { return std::min(bx - 1, static_cast<int>(v / side_x)); }
int NodeBins::bin_y(double v) const { return std::clamp(static_cast<int>((v - y_low) / side_y), 0, by - 1); }
int NodeBins::bin_z(double v) const { return std::min(bz - 1, static_cast<int>(v / side_z)); }

namespace {

double wrap(double v, double period) {
  const double w = v - period * std::floor(v / period);
  return w >= period ? 0.0 : w;
}

// Refills b, reusing its buffers.
void bin_nodes(const std::vector<std::vector<Vec3>>& x, double range, double period_x, double period_z,
               NodeBins& b) {
  double y_low = 1e300, y_high = -1e300;
  std::size_t total = 0;
  for (const auto& cell : x) {
    total += cell.size();
    for (const Vec3& p : cell) y_low = std::min(y_low, p.y()), y_high = std::max(y_high, p.y());
  }
  // At least three bins per periodic direction, so that the 27 neighbours are distinct.
  b.bx = std::max(3, static_cast<int>(period_x / range));
  b.bz = std::max(3, static_cast<int>(period_z / range));
  b.by = std::max(1, static_cast<int>((y_high - y_low) / range));
  b.side_x = period_x / b.bx;
  b.side_z = period_z / b.bz;
  b.side_y = std::max(range, (y_high - y_low) / b.by);
  b.y_low = y_low;
  const std::size_t bins = static_cast<std::size_t>(b.bx) * b.by * b.bz;
  b.start.assign(bins + 1, 0);
  b.bin_of.resize(total);
  b.entries.resize(total);
  b.packed.resize(total);
  std::size_t e = 0;
  for (std::uint32_t i = 0; i < x.size(); ++i)
    for (std::uint32_t m = 0; m < x[i].size(); ++m, ++e) {
      const Vec3 p(wrap(x[i][m].x(), period_x), x[i][m].y(), wrap(x[i][m].z(), period_z));
      b.bin_of[e] = static_cast<std::uint32_t>(b.index(b.bin_x(p.x()), b.bin_y(p.y()), b.bin_z(p.z())));
      ++b.start[b.bin_of[e] + 1];
    }
  for (std::size_t k = 0; k < bins; ++k) b.start[k + 1] += b.start[k];
  b.fill = b.start;
  e = 0;
  for (std::uint32_t i = 0; i < x.size(); ++i)
    for (std::uint32_t m = 0; m < x[i].size(); ++m, ++e) {
      const std::uint32_t slot = b.fill[b.bin_of[e]]++;
      b.entries[slot] = {i, m};
      b.packed[slot] = {static_cast<float>(wrap(x[i][m].x(), period_x)), static_cast<float>(x[i][m].y()),
                        static_cast<float>(wrap(x[i][m].z(), period_z)), i};
    }
}

// Calls visit(d, r2) for every node of another cell within sqrt(range2) of entry e, with
// d the vector from that node to e's node (nearest periodic image).
template <class Visit>
void for_each_partner(const NodeBins& b, long e, double range2, double period_x, double period_z, Visit&& visit) {
  const NodeBins::Packed self = b.packed[e];
  const int ix = b.bin_x(self.x), iy = b.bin_y(self.y), iz = b.bin_z(self.z);
  // Scans the entries [from, to) of one x-image and z-image of the neighbourhood.
  auto scan = [&](std::uint32_t from, std::uint32_t to, float shift_x, float shift_z) {
    const float qx = self.x - shift_x, qy = self.y, qz = self.z - shift_z;
    for (std::uint32_t o = from; o < to; ++o) {
      const NodeBins::Packed& n = b.packed[o];
      const float dx = qx - n.x, dy = qy - n.y, dz = qz - n.z;
      const float r2 = dx * dx + dy * dy + dz * dz;
      if (r2 >= range2 || n.cell == self.cell) continue;
      visit(Vec3(dx, dy, dz), static_cast<double>(r2));
    }
  };
  for (int ddx = -1; ddx <= 1; ++ddx) {
    // A neighbour bin across the seam holds positions one period away.
    int jx = ix + ddx;
    const float shift_x = jx < 0 ? -period_x : (jx >= b.bx ? period_x : 0.0f);
    jx = jx < 0 ? jx + b.bx : (jx >= b.bx ? jx - b.bx : jx);
    for (int ddy = -1; ddy <= 1; ++ddy) {
      const int jy = iy + ddy;
      if (jy < 0 || jy >= b.by) continue;
      if (iz >= 1 && iz + 1 < b.bz) {  // the three z-bins are one run of entries
        scan(b.start[b.index(jx, jy, iz - 1)], b.start[b.index(jx, jy, iz + 1) + 1], shift_x, 0.0f);
        continue;
      }
      for (int ddz = -1; ddz <= 1; ++ddz) {
        int jz = iz + ddz;
        const float shift_z = jz < 0 ? -period_z : (jz >= b.bz ? period_z : 0.0f);
        jz = jz < 0 ? jz + b.bz : (jz >= b.bz ? jz - b.bz : jz);
        const int k = b.index(jx, jy, jz);
        scan(b.start[k], b.start[k + 1], shift_x, shift_z);
      }
    }
  }
}

}  // namespace

ContactCount add_contact_forces(const std::vector<std::vector<Vec3>>& x, double range, double strength,
                                double period_x, double period_z, std::vector<std::vector<Vec3>>& f, NodeBins& b) {
  ContactCount count;
  if (!(range > 0.0) || !(strength > 0.0) || x.empty()) return count;
  bin_nodes(x, range, period_x, period_z, b);
  const double floor = 0.2 * range;
  const long entries = static_cast<long>(b.entries.size());
  long pairs = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : pairs)
  for (long e = 0; e < entries; ++e) {
    Vec3 force = Vec3::Zero();
    for_each_partner(b, e, range * range, period_x, period_z, [&](const Vec3& d, double r2) {
      const double r = std::sqrt(r2);
      force += (strength * (range / std::max(r, floor) - 1.0) / std::max(r, 1e-12)) * d;
      ++pairs;
    });
    f[b.entries[e].first][b.entries[e].second] += force;
  }
  count.node_pairs = pairs;
  return count;
}

ContactCount separate_close_nodes(std::vector<std::vector<Vec3>>& x, double gap, double period_x,
                                  double period_z, NodeBins& b) {
  ContactCount count;
  if (!(gap > 0.0) || x.empty()) return count;
  bin_nodes(x, gap, period_x, period_z, b);
  const long entries = static_cast<long>(b.entries.size());
  std::vector<Vec3>& shift = b.shift;
  shift.assign(b.entries.size(), Vec3::Zero());
  long pairs = 0;
#pragma omp parallel for schedule(dynamic, 256) reduction(+ : pairs)
  for (long e = 0; e < entries; ++e) {
    double nearest2 = gap * gap;
    Vec3 away = Vec3::Zero();
    for_each_partner(b, e, gap * gap, period_x, period_z, [&](const Vec3& d, double r2) {
      ++pairs;
      if (r2 < nearest2) nearest2 = r2, away = d;
    });
    const double r = std::sqrt(nearest2);
    // Half the shortfall: the partner, seeing this node as its nearest, moves the other half.
    if (r < gap) shift[e] = (0.5 * (gap - r) / std::max(r, 1e-12)) * away;
  }
  for (long e = 0; e < entries; ++e) x[b.entries[e].first][b.entries[e].second] += shift[e];
  count.node_pairs = pairs;
  return count;
}

}  // namespace rbcal::solver
