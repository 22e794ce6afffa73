#include "solver/simulation/detail/cell_seeding.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

namespace rbcal::solver {

namespace {

struct Extent {
  Vec3 lo, hi;
};

Extent extent(const TriangleMesh& m, const Eigen::Matrix3d& rot) {
  Extent e{Vec3::Constant(1e300), Vec3::Constant(-1e300)};
  for (const Vec3& v : m.vertices) {
    const Vec3 p = rot * v;
    e.lo = e.lo.cwiseMin(p);
    e.hi = e.hi.cwiseMax(p);
  }
  return e;
}

// Axis-angle (degrees) of a rotation matrix, as CellPlacement stores it.
std::array<double, 4> axis_angle(const Eigen::Matrix3d& rot) {
  const Eigen::AngleAxisd aa(rot);
  return {aa.axis().x(), aa.axis().y(), aa.axis().z(), aa.angle() * 180.0 / std::numbers::pi};
}

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));  // uniform on SO(3) once normalised
  return q.normalized().toRotationMatrix();
}


// A box that holds one disc (axis z), and the slots of a box: a grid of the discs'
// bounding boxes (stage 2); if that holds fewer than n, hexagonal rows in the x-y plane
// (stage 3: four rows instead of three in an 8 a high box, 12 instead of 9 discs per
// layer), each slot then the square around its disc's circle, centred on the row point.
struct Slot {
  Vec3 corner, size;
  bool hexagonal = false;  // the disc sits on the row point: no slack in x and y
};

std::vector<Slot> disc_slots(const TriangleMesh& reference, const std::array<double, 3>& box, double wall_gap, int n) {
  const Extent flat = extent(reference, Eigen::Matrix3d::Identity());
  const Vec3 size = flat.hi - flat.lo;  // about (2, 2, thickness)
  const double usable_h = box[1] - 2.0 * wall_gap;
  const int sx = static_cast<int>(std::floor(box[0] / size.x()));
  const int sy = static_cast<int>(std::floor(usable_h / size.y()));
  const int sz = static_cast<int>(std::floor(box[2] / size.z()));
  std::vector<Slot> slots;
  const double thick = box[2] / sz;
  if (static_cast<long>(sx) * sy * sz >= n) {
    const Vec3 slot(box[0] / sx, usable_h / sy, thick);
    for (int ix = 0; ix < sx; ++ix)
      for (int iy = 0; iy < sy; ++iy)
        for (int iz = 0; iz < sz; ++iz)
          slots.push_back({Vec3(-0.5 * box[0] + ix * slot.x(), -0.5 * box[1] + wall_gap + iy * slot.y(),
                                -0.5 * box[2] + iz * slot.z()),
                           slot});
    return slots;
  }
  // Hexagonal rows of circles of diameter d (the disc's widest extent in any spin) at the
  // pitch p >= d along x; neighbouring rows are offset by p / 2 and h = sqrt(d^2 - p^2/4)
  // apart, so that circles of neighbouring rows just touch.
  double radius = 0.0;
  for (const Vec3& v : reference.vertices) radius = std::max(radius, std::hypot(v.x(), v.y()));
  const double d = 2.0 * radius;
  const int per_row = static_cast<int>(std::floor(box[0] / d + 1e-9));
  if (per_row < 1 || usable_h < d) return slots;
  const double pitch = box[0] / per_row;
  // Rows two apart are aligned, so they must also be d apart: h >= d / 2.
  const double h = std::max(std::sqrt(std::max(0.0, d * d - 0.25 * pitch * pitch)), 0.5 * d);
  const int rows = 1 + static_cast<int>(std::floor((usable_h - d) / h + 1e-9));
  const double y0 = -0.5 * box[1] + wall_gap + 0.5 * (usable_h - d - (rows - 1) * h);  // rows centred in y
  for (int r = 0; r < rows; ++r)
    for (int ix = 0; ix < per_row; ++ix)
      for (int iz = 0; iz < sz; ++iz) {
        const double x = -0.5 * box[0] + (ix + 0.5 * (r % 2)) * pitch + 0.5 * (pitch - d);
        slots.push_back({Vec3(x, y0 + r * h, -0.5 * box[2] + iz * thick), Vec3(d, d, thick), true});
      }
  return slots;
}

}  // namespace

SeedingResult seed_cells(double target_phi, const TriangleMesh& reference, const std::array<double, 3>& box,
                         double wall_gap, std::uint64_t seed) {
  if (!(target_phi > 0.0 && target_phi < 0.7)) throw std::invalid_argument("seeding: phi must be in (0, 0.7)");
  const double v_cell = enclosed_volume(reference.vertices, reference.triangles);
  const double v_box = box[0] * box[1] * box[2];
  const int n = static_cast<int>(std::lround(target_phi * v_box / v_cell));
  if (n < 1) throw std::invalid_argument("seeding: phi " + std::to_string(target_phi) + " asks for no cell in this box");
  SeedingResult result;
  result.phi = n * v_cell / v_box;
  std::mt19937_64 rng(seed);

  // Stage 1: random sequential addition with circumscribed spheres of radius 1.
  const double half_h = 0.5 * box[1] - wall_gap - 1.0;  // centre's reach in y
  if (half_h > 0.0) {
    std::uniform_real_distribution<double> ux(-0.5 * box[0], 0.5 * box[0]), uy(-half_h, half_h),
        uz(-0.5 * box[2], 0.5 * box[2]);
    std::vector<Vec3> centres;
    const long max_attempts = 2000L * n;
    for (long attempt = 0; attempt < max_attempts && static_cast<int>(centres.size()) < n; ++attempt) {
      const Vec3 c(ux(rng), uy(rng), uz(rng));
      bool free = true;
      for (const Vec3& o : centres) {
        Vec3 d = c - o;
        d.x() -= box[0] * std::round(d.x() / box[0]);  // periodic in x and z
        d.z() -= box[2] * std::round(d.z() / box[2]);
        if (d.squaredNorm() < 4.0) {
          free = false;
          break;
        }
      }
      if (free) centres.push_back(c);
    }
    if (static_cast<int>(centres.size()) == n) {
      for (const Vec3& c : centres) result.placements.push_back({{c.x(), c.y(), c.z()}, axis_angle(random_rotation(rng))});
      return result;
    }
  }

  // Stage 2: slots, disc axes along z; stage 3 where stage 2 has too few slots.
  const std::vector<Slot> slots = disc_slots(reference, box, wall_gap, n);
  if (static_cast<long>(slots.size()) < n) {
    const Extent flat = extent(reference, Eigen::Matrix3d::Identity());
    const Vec3 size = flat.hi - flat.lo;
    throw std::invalid_argument("seeding: " + std::to_string(n) + " cells do not fit (" + std::to_string(slots.size()) +
                                " slots for discs of " + std::to_string(size.x()) + " x " + std::to_string(size.y()) +
                                " x " + std::to_string(size.z()) + " a); lower phi or use a thinner profile");
  }
  std::vector<int> order(slots.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::shuffle(order.begin(), order.end(), rng);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < n; ++k) {
    const Slot& slot = slots[order[k]];
    // Spin about the symmetry axis: the disc's extent is unchanged (axisymmetric shape).
    const Eigen::Matrix3d rot = Eigen::AngleAxisd(2.0 * std::numbers::pi * unit(rng), Vec3::UnitZ()).toRotationMatrix();
    const Extent e = extent(reference, rot);
    const Vec3 slack = (slot.size - (e.hi - e.lo)).cwiseMax(0.0);
    Vec3 c = slot.corner - e.lo + Vec3(slack.x() * unit(rng), slack.y() * unit(rng), slack.z() * unit(rng));
    if (slot.hexagonal) c.head<2>() = slot.corner.head<2>() + 0.5 * slot.size.head<2>();  // the axis on the row point
    result.placements.push_back({{c.x(), c.y(), c.z()}, axis_angle(rot)});
  }
  result.used_slots = true;
  return result;
}

}  // namespace rbcal::solver
