#include "solver/coupling/inside_fraction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "solver/coupling/kernel_stencil.hpp"

namespace rbcal::solver {

namespace {

// Offsets of the scan lines from the lattice columns (irrational, far below dx).
constexpr double kLineOffsetX = 1.0e-7 * 3.14159265358979;
constexpr double kLineOffsetY = 1.0e-7 * 2.71828182845905;

// Lattice columns (x) per chunk of the parallel apply.
constexpr int kColumnsPerChunk = 2;

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
  // Clear the previous footprint (each node listed once: parallel), keep it as previous_.
  previous_.swap(inside_);
  const long previous_chunks = static_cast<long>(previous_.size());
#pragma omp parallel for schedule(dynamic)
  for (long k = 0; k < previous_chunks; ++k)
    for (const std::size_t node : previous_[k]) {
      alpha_[node] = 0.0;
      marked_[node] = 0;
    }
  // The scan-line crossings of each mesh are independent (parallel).
  crossings_.resize(positions.size());
#pragma omp parallel for schedule(dynamic)
  for (std::size_t i = 0; i < positions.size(); ++i) crossings_of(*positions[i], triangles, crossings_[i]);
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (crossings_[i].oversized)
      throw std::runtime_error("inside fraction: cell " + std::to_string(i) +
                               " spans more than the lattice in x or y (the membrane has blown up)");
  // Applying them to alpha: neighbouring cells share boundary nodes, but a node lies in
  // one lattice column, so chunks of columns run in parallel. Within a chunk the cells
  // go in order, so every node sums its cells in the same order as a serial pass would,
  // whatever the thread count; the footprint stays in the chunks' lists (joining them was
  // a tenth of a rebuild).
  const int chunks = (nx_ + kColumnsPerChunk - 1) / kColumnsPerChunk;
  inside_.resize(chunks);
#pragma omp parallel for schedule(dynamic)
  for (int k = 0; k < chunks; ++k) {
    inside_[k].clear();
    const int lo = k * kColumnsPerChunk, hi = std::min(nx_, lo + kColumnsPerChunk);
    for (const Crossings& c : crossings_) apply(c, lo, hi, inside_[k]);
  }
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
  // The crossings are hits[0, found): a buffer per thread, warm from the thread's previous
  // mesh (one per mesh came cold from memory at every build), grown when a mesh needs more.
  thread_local std::vector<Hit> hits;
  std::size_t found = 0;
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
    if (p1 < p0 || q1 < q0) continue;
    // Every line of the triangle's box is tested and written; only those inside advance
    // the end (the test's outcome is a coin toss per line, and a mispredicted branch on it
    // cost more than the test).
    const std::size_t room = static_cast<std::size_t>(p1 - p0 + 1) * (q1 - q0 + 1);
    if (found + room > hits.size()) hits.resize(std::max(2 * hits.size(), found + room));
    Hit* const slot = hits.data();
    for (int p = p0; p <= p1; ++p)
      for (int q = q0; q <= q1; ++q) {
        const double px = line_x(p), py = line_y(q);
        // Barycentric weights of (px, py) in the projected triangle.
        const double wa = ((b.x() - px) * (c.y() - py) - (b.y() - py) * (c.x() - px)) * inv_area2;
        const double wb = ((c.x() - px) * (a.y() - py) - (c.y() - py) * (a.x() - px)) * inv_area2;
        const double wc = 1.0 - wa - wb;
        slot[found] = {wa * a.z() + wb * b.z() + wc * c.z(), (p - pbase) * qcount + (q - qbase), sign};
        found += (wa >= 0.0) & (wb >= 0.0) & (wc >= 0.0);
      }
  }
  // Order by line (counting sort), then by z within each line (a handful of hits each).
  auto& start = out.line_start;
  start.assign(static_cast<std::size_t>(pcount) * qcount + 1, 0);
  for (std::size_t h = 0; h < found; ++h) ++start[hits[h].line + 1];
  for (std::size_t l = 1; l < start.size(); ++l) start[l] += start[l - 1];
  out.hits.resize(found);
  for (std::size_t h = 0; h < found; ++h) out.hits[start[hits[h].line]++] = hits[h];  // start[l]: then the end of line l
  for (std::size_t l = 0, begin = 0; l + 1 < start.size(); begin = start[l], ++l)
    for (std::size_t m = begin + 1; m < static_cast<std::size_t>(start[l]); ++m)
      for (std::size_t k = m; k > begin && out.hits[k].z < out.hits[k - 1].z; --k) std::swap(out.hits[k], out.hits[k - 1]);
}

void InsideFraction::apply(const Crossings& c, int column_lo, int column_hi, std::vector<std::size_t>& reached) {
  const double weight = 1.0 / (sub_ * sub_);  // each line stands for 1/S^2 of its column
  const int pbase = c.pbase, qbase = c.qbase, qcount = c.qcount;
  if (c.hits.empty() || qcount == 0) return;
  // The mesh's lines from column p: lines (p - pbase) qcount ... + qcount - 1, hits found
  // through line_start (after the sort, line_start[l] is the end of line l's hits).
  const int pcount = static_cast<int>((c.line_start.size() - 1) / qcount);
  // Only the lines in the chunk's columns, found per periodic image of the chunk (the mesh
  // is narrower than the box, so a few images), in ascending p as a pass over all lines
  // would visit them (every chunk testing every line of every mesh cost a sixth of this
  // function's time).
  const int first_column = floor_div(pbase, sub_), last_column = floor_div(pbase + pcount - 1, sub_);
  for (int image = floor_div(first_column, nx_) - 1; image <= floor_div(last_column, nx_) + 1; ++image) {
    const int p_end = std::min(pbase + pcount, (column_hi + image * nx_) * sub_);
    for (int p = std::max(pbase, (column_lo + image * nx_) * sub_); p < p_end; ++p) {
      const int pl = p - pbase;
      const int column_x = floor_div(p, sub_) - image * nx_;
      for (int ql = 0; ql < qcount; ++ql) {
        const int line = pl * qcount + ql;
        const std::size_t begin = line == 0 ? 0 : c.line_start[line - 1], end = c.line_start[line];
        if (end - begin < 2) continue;
        const int q = qbase + ql;
        const int j = static_cast<int>(std::floor(static_cast<double>(q) / sub_));
        if (j < 0 || j >= ny_) continue;  // beyond a wall: no nodes
        const std::size_t column = (static_cast<std::size_t>(column_x) * ny_ + j) * nz_;
        int winding = 0;
        for (std::size_t m = begin; m + 1 < end; ++m) {
          winding += c.hits[m].sign;
          if (winding <= 0) continue;
          // [z0, z1] is inside: give each node k the overlap with [k - 1/2, k + 1/2].
          const double z0 = c.hits[m].z, z1 = c.hits[m + 1].z;
          const int k0 = static_cast<int>(std::floor(z0 + 0.5)), k1 = static_cast<int>(std::floor(z1 + 0.5));
          // k wrapped into the box once per interval, then stepped.
          for (int k = k0, kz = wrap_index(k0, nz_); k <= k1; ++k, kz = kz + 1 < nz_ ? kz + 1 : 0) {
            const double overlap = std::min(z1, k + 0.5) - std::max(z0, k - 0.5);
            if (overlap <= 0.0) continue;
            const std::size_t node = column + kz;
            alpha_[node] = std::min(1.0, alpha_[node] + weight * overlap);
            if (!marked_[node]) {
              marked_[node] = 1;
              reached.push_back(node);
            }
          }
        }
      }
    }
  }
}

}  // namespace rbcal::solver
