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
  b.wrapped.resize(total);
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
      b.wrapped[slot] = Vec3(wrap(x[i][m].x(), period_x), x[i][m].y(), wrap(x[i][m].z(), period_z));
    }
}

// Calls visit(d, r2) for every node of another cell within sqrt(range2) of entry e, with
// d the vector from that node to e's node (nearest periodic image).
template <class Visit>
void for_each_partner(const NodeBins& b, long e, double range2, double period_x, double period_z, Visit&& visit) {
  const std::uint32_t cell = b.entries[e].first;
  const Vec3& p = b.wrapped[e];
  const int ix = b.bin_x(p.x()), iy = b.bin_y(p.y()), iz = b.bin_z(p.z());
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
        const int k = b.index(jx < 0 ? jx + b.bx : (jx >= b.bx ? jx - b.bx : jx), jy,
                              jz < 0 ? jz + b.bz : (jz >= b.bz ? jz - b.bz : jz));
        for (std::uint32_t o = b.start[k]; o < b.start[k + 1]; ++o) {
          const Vec3 d = q - b.wrapped[o];
          const double r2 = d.squaredNorm();
          if (r2 >= range2 || b.entries[o].first == cell) continue;
          visit(d, r2);
        }
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
