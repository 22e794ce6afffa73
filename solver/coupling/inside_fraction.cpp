#include "solver/coupling/inside_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace rbcal::solver {

namespace {

// Offsets of the scan lines from the lattice columns (irrational, far below dx).
constexpr double kLineOffsetX = 1.0e-7 * 3.14159265358979;
constexpr double kLineOffsetY = 1.0e-7 * 2.71828182845905;

int wrap(int i, int n) { return ((i % n) + n) % n; }

}  // namespace

InsideFraction::InsideFraction(int nx, int ny, int nz, int lines_per_spacing)
    : nx_(nx),
      ny_(ny),
      nz_(nz),
      sub_(lines_per_spacing),
      alpha_(static_cast<std::size_t>(nx) * ny * nz, 0.0),
      marked_(alpha_.size(), 0) {}

void InsideFraction::update(const std::vector<const std::vector<Vec3>*>& positions,
                            const std::vector<Triangle>& triangles) {
  // Clear the previous footprint, then record each node of the new one once (marks).
  std::vector<std::size_t> previous;
  previous.reserve(inside_.size());
  for (std::size_t n : inside_) {
    alpha_[n] = 0.0;
    marked_[n] = 0;
    previous.push_back(n);
  }
  inside_.clear();
  // The scan-line crossings of each mesh are independent (parallel); applying them to
  // alpha is not (neighbouring cells share boundary nodes), so it runs in order.
  crossings_.resize(positions.size());
#pragma omp parallel for schedule(dynamic)
  for (std::size_t i = 0; i < positions.size(); ++i) crossings_of(*positions[i], triangles, crossings_[i]);
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (crossings_[i].oversized)
      throw std::runtime_error("inside fraction: cell " + std::to_string(i) +
                               " spans more than the lattice in x or y (the membrane has blown up)");
  for (const Crossings& c : crossings_) apply(c);
  // Changed nodes: the old footprint and the new (a node may appear in both).
  touched_ = std::move(previous);
  touched_.insert(touched_.end(), inside_.begin(), inside_.end());
}

void InsideFraction::crossings_of(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles,
                                  Crossings& out) const {
  // Scan lines are numbered on the fine grid: line (p, q) sits at
  // x = (p + 1/2) / S - 1/2 (+ offset), y likewise, and belongs to column floor((p)/S).
  const double h = 1.0 / sub_;
  auto line_x = [&](int p) { return (p + 0.5) * h - 0.5 + kLineOffsetX; };
  auto line_y = [&](int q) { return (q + 0.5) * h - 0.5 + kLineOffsetY; };
  // Crossings per scan line, in a flat grid over the mesh's bounding box of lines.
  const Bounds box = bounding_box(x);
  const double xmin = box.lo.x(), xmax = box.hi.x(), ymin = box.lo.y(), ymax = box.hi.y();
  // A cell cannot be wider than the box; one that is has blown up, and its grid of scan
  // lines would grow with it (an unguarded run reached 7 GB). NaN coordinates count too.
  out.oversized = !(xmax - xmin < nx_ && ymax - ymin < ny_ + 1);
  if (out.oversized) {
    out.hits.clear();
    return;
  }
  auto first_line = [&](double lo, double offset) { return static_cast<int>(std::ceil((lo + 0.5 - offset) * sub_ - 0.5)); };
  auto last_line = [&](double hi, double offset) { return static_cast<int>(std::floor((hi + 0.5 - offset) * sub_ - 0.5)); };
  const int pbase = first_line(xmin, kLineOffsetX), qbase = first_line(ymin, kLineOffsetY);
  const int qcount = std::max(0, last_line(ymax, kLineOffsetY) - qbase + 1);
  const int pcount = std::max(0, last_line(xmax, kLineOffsetX) - pbase + 1);
  out.pbase = pbase;
  out.qbase = qbase;
  out.qcount = qcount;
  auto& hits = out.unsorted;
  hits.clear();
  for (const Triangle& t : triangles) {
    const Vec3 &a = x[t[0]], &b = x[t[1]], &c = x[t[2]];
    const double area2 = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    if (area2 == 0.0) continue;  // edge-on to the scan lines
    const int sign = area2 > 0.0 ? -1 : 1;  // normal along +z: leaving the interior
    const double inv_area2 = 1.0 / area2;
    const int p0 = first_line(std::min({a.x(), b.x(), c.x()}), kLineOffsetX);
    const int p1 = last_line(std::max({a.x(), b.x(), c.x()}), kLineOffsetX);
    const int q0 = first_line(std::min({a.y(), b.y(), c.y()}), kLineOffsetY);
    const int q1 = last_line(std::max({a.y(), b.y(), c.y()}), kLineOffsetY);
    for (int p = p0; p <= p1; ++p)
      for (int q = q0; q <= q1; ++q) {
        const double px = line_x(p), py = line_y(q);
        // Barycentric weights of (px, py) in the projected triangle.
        const double wa = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) * inv_area2;
        const double wb = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) * inv_area2;
        const double wc = 1.0 - wa - wb;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        hits.push_back({(p - pbase) * qcount + (q - qbase), wa * a.z() + wb * b.z() + wc * c.z(), sign});
      }
  }
  // Order by line (counting sort), then by z within each line (a handful of hits each).
  auto& start = out.line_start;
  start.assign(static_cast<std::size_t>(pcount) * qcount + 1, 0);
  for (const Hit& h : hits) ++start[h.line + 1];
  for (std::size_t l = 1; l < start.size(); ++l) start[l] += start[l - 1];
  out.hits.resize(hits.size());
  for (const Hit& h : hits) out.hits[start[h.line]++] = h;  // start[l] ends as the end of line l
  for (std::size_t l = 0, begin = 0; l + 1 < start.size(); begin = start[l], ++l)
    for (std::size_t m = begin + 1; m < static_cast<std::size_t>(start[l]); ++m)
      for (std::size_t k = m; k > begin && out.hits[k].z < out.hits[k - 1].z; --k) std::swap(out.hits[k], out.hits[k - 1]);
}

void InsideFraction::apply(const Crossings& c) {
  const double weight = 1.0 / (sub_ * sub_);  // each line stands for 1/S^2 of its column
  const int pbase = c.pbase, qbase = c.qbase, qcount = c.qcount;
  for (std::size_t begin = 0, end = 0; begin < c.hits.size(); begin = end) {
    end = begin;
    while (end < c.hits.size() && c.hits[end].line == c.hits[begin].line) ++end;
    const int line = c.hits[begin].line;
    const int p = pbase + line / qcount, q = qbase + line % qcount;
    const int i = static_cast<int>(std::floor(static_cast<double>(p) / sub_));
    const int j = static_cast<int>(std::floor(static_cast<double>(q) / sub_));
    if (j < 0 || j >= ny_) continue;  // beyond a wall: no nodes
    const std::size_t column = (static_cast<std::size_t>(wrap(i, nx_)) * ny_ + j) * nz_;
    int winding = 0;
    for (std::size_t m = begin; m + 1 < end; ++m) {
      winding += c.hits[m].sign;
      if (winding <= 0) continue;
      // [z0, z1] is inside: give each node k the overlap with [k - 1/2, k + 1/2].
      const double z0 = c.hits[m].z, z1 = c.hits[m + 1].z;
      const int k0 = static_cast<int>(std::floor(z0 + 0.5)), k1 = static_cast<int>(std::floor(z1 + 0.5));
      for (int k = k0; k <= k1; ++k) {
        const double overlap = std::min(z1, k + 0.5) - std::max(z0, k - 0.5);
        if (overlap <= 0.0) continue;
        const std::size_t node = column + wrap(k, nz_);
        alpha_[node] = std::min(1.0, alpha_[node] + weight * overlap);
        if (!marked_[node]) {
          marked_[node] = 1;
          inside_.push_back(node);
        }
      }
    }
  }
}

}  // namespace rbcal::solver
