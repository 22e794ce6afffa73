#include "solver/coupling/inside_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace rbcal::solver {

namespace {

// Offsets of the scan lines from the lattice columns (irrational, far below dx).
constexpr double kLineOffsetX = 1.0e-7 * 3.14159265358979;
constexpr double kLineOffsetY = 1.0e-7 * 2.71828182845905;

int wrap(int i, int n) { return ((i % n) + n) % n; }

}  // namespace

InsideFraction::InsideFraction(int nx, int ny, int nz, int lines_per_spacing)
    : nx_(nx), ny_(ny), nz_(nz), sub_(lines_per_spacing), alpha_(static_cast<std::size_t>(nx) * ny * nz, 0.0) {}

double InsideFraction::total() const {
  double s = 0.0;
  for (std::size_t n : touched_) s += alpha_[n];
  return s;
}

void InsideFraction::update(const std::vector<const std::vector<Vec3>*>& positions,
                            const std::vector<Triangle>& triangles) {
  for (std::size_t n : touched_) alpha_[n] = 0.0;
  previous_.swap(touched_);
  touched_.clear();
  for (const auto* x : positions) add_mesh(*x, triangles);
  std::sort(touched_.begin(), touched_.end());
  touched_.erase(std::unique(touched_.begin(), touched_.end()), touched_.end());
  // Nodes that were inside before but not now must also be reported as changed.
  std::vector<std::size_t> changed;
  std::set_union(touched_.begin(), touched_.end(), previous_.begin(), previous_.end(), std::back_inserter(changed));
  touched_.swap(changed);
}

void InsideFraction::add_mesh(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles) {
  // Scan lines are numbered on the fine grid: line (p, q) sits at
  // x = (p + 1/2) / S - 1/2 (+ offset), y likewise, and belongs to column floor((p)/S).
  const double h = 1.0 / sub_;
  auto line_x = [&](int p) { return (p + 0.5) * h - 0.5 + kLineOffsetX; };
  auto line_y = [&](int q) { return (q + 0.5) * h - 0.5 + kLineOffsetY; };
  std::map<std::pair<int, int>, std::vector<std::pair<double, int>>> crossings;
  for (const Triangle& t : triangles) {
    const Vec3 &a = x[t[0]], &b = x[t[1]], &c = x[t[2]];
    const double area2 = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (area2 == 0.0) continue;  // edge-on to the scan lines
    const int sign = area2 > 0.0 ? -1 : 1;  // normal along +z: leaving the interior
    const int p0 = static_cast<int>(std::ceil((std::min({a.x(), b.x(), c.x()}) + 0.5 - kLineOffsetX) * sub_ - 0.5));
    const int p1 = static_cast<int>(std::floor((std::max({a.x(), b.x(), c.x()}) + 0.5 - kLineOffsetX) * sub_ - 0.5));
    const int q0 = static_cast<int>(std::ceil((std::min({a.y(), b.y(), c.y()}) + 0.5 - kLineOffsetY) * sub_ - 0.5));
    const int q1 = static_cast<int>(std::floor((std::max({a.y(), b.y(), c.y()}) + 0.5 - kLineOffsetY) * sub_ - 0.5));
    for (int p = p0; p <= p1; ++p)
      for (int q = q0; q <= q1; ++q) {
        const double px = line_x(p), py = line_y(q);
        // Barycentric weights of (px, py) in the projected triangle.
        const double wa = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) / area2;
        const double wb = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) / area2;
        const double wc = 1.0 - wa - wb;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        crossings[{p, q}].emplace_back(wa * a.z() + wb * b.z() + wc * c.z(), sign);
      }
  }
  const double weight = h * h;  // each line stands for 1/S^2 of its column
  for (auto& [line, list] : crossings) {
    const auto [p, q] = line;
    const int i = static_cast<int>(std::floor(static_cast<double>(p) / sub_));
    const int j = static_cast<int>(std::floor(static_cast<double>(q) / sub_));
    if (j < 0 || j >= ny_) continue;  // beyond a wall: no nodes
    std::sort(list.begin(), list.end());
    const std::size_t column = (static_cast<std::size_t>(wrap(i, nx_)) * ny_ + j) * nz_;
    int winding = 0;
    for (std::size_t m = 0; m + 1 < list.size(); ++m) {
      winding += list[m].second;
      if (winding <= 0) continue;
      // [z0, z1] is inside: give each node k the overlap with [k - 1/2, k + 1/2].
      const double z0 = list[m].first, z1 = list[m + 1].first;
      const int k0 = static_cast<int>(std::floor(z0 + 0.5)), k1 = static_cast<int>(std::floor(z1 + 0.5));
      for (int k = k0; k <= k1; ++k) {
        const double overlap = std::min(z1, k + 0.5) - std::max(z0, k - 0.5);
        if (overlap <= 0.0) continue;
        const std::size_t node = column + wrap(k, nz_);
        alpha_[node] = std::min(1.0, alpha_[node] + weight * overlap);
        touched_.push_back(node);
      }
    }
  }
}

}  // namespace rbcal::solver
