#pragma once
// The arithmetic of one membrane element, shared by the CPU loops (which gather blocks of
// elements and vectorise over them) and the device path: the in-plane elastic forces of a
// triangle (membrane_elasticity.hpp), the bending forces of a hinge (dihedral_bending.hpp)
// and a triangle's share of the enclosed volume and its gradient (volume_constraint.hpp).
// Coordinates come as x y z of each node in turn, `stride` doubles apart (1 for a flat
// array; the CPU loops pass the columns of their blocks, so that the function inlines into
// a loop the compiler vectorises, with no per-lane arrays); outputs likewise.
#include <cmath>

#include "solver/device/host_device.hpp"
#include "solver/membrane/strain_energy.hpp"

namespace rbcal::solver {

// Reference data of one triangle: its inverse reference metric G^-1, 1 / det G and area A0.
struct ElasticElementReference {
  double inv_g11, inv_g12, inv_g22, inv_det_g, area;
};

// Triangle (a, b, c) at x = {a, b, c}: writes -dW/dx of b (out[0..2]) and c (out[3..5]);
// a takes minus their sum. Returns the element's energy A0 w(I1, I2).
template <MembraneLaw law>
RBCAL_HD inline double elastic_element_forces(const double* x, int stride, const ElasticElementReference& r, double gs,
                                              double c, double* out, int out_stride) {
  const double e1x = x[3 * stride] - x[0], e1y = x[4 * stride] - x[1 * stride], e1z = x[5 * stride] - x[2 * stride];
  const double e2x = x[6 * stride] - x[0], e2y = x[7 * stride] - x[1 * stride], e2z = x[8 * stride] - x[2 * stride];
  const double g11 = e1x * e1x + e1y * e1y + e1z * e1z;
  const double g12 = e1x * e2x + e1y * e2y + e1z * e2z;
  const double g22 = e2x * e2x + e2y * e2y + e2z * e2z;
  const double i1 = r.inv_g11 * g11 + 2.0 * r.inv_g12 * g12 + r.inv_g22 * g22 - 2.0;
  const double i2 = (g11 * g22 - g12 * g12) * r.inv_det_g - 1.0;
  const EnergyDensity w = law == MembraneLaw::Skalak ? skalak(i1, i2, gs, c) : neo_hookean(i1, i2, gs);
  // dI1/de1 = 2 (G^11 e1 + G^12 e2), dI2/de1 = 2 (g22 e1 - g12 e2) / det G; likewise for e2.
  const double a = 2.0 * r.area * w.dw_dI1;
  const double b = 2.0 * r.area * w.dw_dI2 * r.inv_det_g;
  const double p11 = a * r.inv_g11 + b * g22, p12 = a * r.inv_g12 - b * g12;
  const double p22 = a * r.inv_g22 + b * g11;
  out[0] = -(p11 * e1x + p12 * e2x);
  out[1 * out_stride] = -(p11 * e1y + p12 * e2y);
  out[2 * out_stride] = -(p11 * e1z + p12 * e2z);
  out[3 * out_stride] = -(p12 * e1x + p22 * e2x);
  out[4 * out_stride] = -(p12 * e1y + p22 * e2y);
  out[5 * out_stride] = -(p12 * e1z + p22 * e2z);
  return r.area * w.w;
}

// Reference data of one hinge: cos and sin of its spontaneous angle, and 1 / the smallest
// |n|^2 (n: twice the area vector) its wings (a, b, c) and (b, a, d) are held at.
struct HingeReference {
  double cos0, sin0, inv_min_n1sq, inv_min_n2sq;
};

// Hinge a-b with wings c and d, x = {a, b, c, d}: writes -dE/dx of the four nodes to
// out[0..11] and the square of the collapsed-wing factor to held_sq (the forces are to be
// scaled by sqrt(held_sq) where it is below 1: dihedral_bending.hpp). Returns
// k_d (1 - cos(theta - theta0)).
RBCAL_HD inline double hinge_forces(const double* x, int stride, const HingeReference& r, double kd, double* out,
                                    int out_stride, double& held_sq) {
  const double ax = x[0], ay = x[1 * stride], az = x[2 * stride];
  const double bx = x[3 * stride], by = x[4 * stride], bz = x[5 * stride];
  const double cx = x[6 * stride], cy = x[7 * stride], cz = x[8 * stride];
  const double dx = x[9 * stride], dy = x[10 * stride], dz = x[11 * stride];
  const double ex = bx - ax, ey = by - ay, ez = bz - az;  // the edge
  const double ux = cx - ax, uy = cy - ay, uz = cz - az;
  const double vx = dx - bx, vy = dy - by, vz = dz - bz;
  // n1 = e x (c - a), n2 = (a - b) x (d - b) = v x e
  const double n1x = ey * uz - ez * uy, n1y = ez * ux - ex * uz, n1z = ex * uy - ey * ux;
  const double n2x = vy * ez - vz * ey, n2y = vz * ex - vx * ez, n2z = vx * ey - vy * ex;
  const double len2 = ex * ex + ey * ey + ez * ez;
  const double n1sq = n1x * n1x + n1y * n1y + n1z * n1z, n2sq = n2x * n2x + n2y * n2y + n2z * n2z;
  // One division and two square roots for |e|, 1/|e|, 1/(|n1| |n2|), 1/|n1|^2 and
  // 1/|n2|^2 (divisions and roots bound the CPU loop; it had seven and three).
  const double len = sqrt(len2);
  const double n1n2sq = n1sq * n2sq;
  const double q = 1.0 / (len * n1n2sq);
  const double inv_len = q * n1n2sq, inv_n1n2sq = q * len;
  // cos and sin of theta - theta0 from those of theta and theta0 (no atan2, sin, cos):
  // |n1 x n2| = |n1||n2| because both normals are perpendicular to the edge.
  const double crx = n1y * n2z - n1z * n2y, cry = n1z * n2x - n1x * n2z, crz = n1x * n2y - n1y * n2x;
  const double sin_t = (crx * ex + cry * ey + crz * ez) * inv_len, cos_t = n1x * n2x + n1y * n2y + n1z * n2z;
  const double inv_r = sqrt(inv_n1n2sq);
  const double cos_delta = (cos_t * r.cos0 + sin_t * r.sin0) * inv_r;
  const double sin_delta = (sin_t * r.cos0 - cos_t * r.sin0) * inv_r;
  // Gradient of the dihedral angle: the wing vertices move along their triangle normals at
  // rate 1/height; the edge vertices take the rest so that the sum and the torque of the
  // gradient vanish.
  const double sc = -len * n2sq * inv_n1n2sq, sd = -len * n1sq * inv_n1n2sq;
  const double gcx = sc * n1x, gcy = sc * n1y, gcz = sc * n1z;
  const double gdx = sd * n2x, gdy = sd * n2y, gdz = sd * n2z;
  const double inv_len2 = inv_len * inv_len;
  const double pc = ((cx - bx) * ex + (cy - by) * ey + (cz - bz) * ez) * inv_len2;
  const double pd = (vx * ex + vy * ey + vz * ez) * inv_len2;
  const double qc = (ux * ex + uy * ey + uz * ez) * inv_len2;
  const double qd = ((dx - ax) * ex + (dy - ay) * ey + (dz - az) * ez) * inv_len2;
  // min(1, |n|^2 / |n_min|^2) over the two wings.
  const double r1 = n1sq * r.inv_min_n1sq, r2 = n2sq * r.inv_min_n2sq;
  held_sq = r1 < r2 ? (r1 < 1.0 ? r1 : 1.0) : (r2 < 1.0 ? r2 : 1.0);
  const double de = -kd * sin_delta;
  out[0] = de * (pc * gcx + pd * gdx);
  out[1 * out_stride] = de * (pc * gcy + pd * gdy);
  out[2 * out_stride] = de * (pc * gcz + pd * gdz);
  out[3 * out_stride] = -de * (qc * gcx + qd * gdx);
  out[4 * out_stride] = -de * (qc * gcy + qd * gdy);
  out[5 * out_stride] = -de * (qc * gcz + qd * gdz);
  out[6 * out_stride] = de * gcx;
  out[7 * out_stride] = de * gcy;
  out[8 * out_stride] = de * gcz;
  out[9 * out_stride] = de * gdx;
  out[10 * out_stride] = de * gdy;
  out[11 * out_stride] = de * gdz;
  return kd * (1.0 - cos_delta);
}

// Triangle (a, b, c) at x = {a, b, c}: writes s times its share of dV/dx of each node,
// s (b x c, c x a, a x b) / 6, and returns 6 times its share of the volume, a . (b x c).
RBCAL_HD inline double triangle_volume_gradient(const double* x, int stride, double s, double* out, int out_stride) {
  const double ax = x[0], ay = x[1 * stride], az = x[2 * stride];
  const double bx = x[3 * stride], by = x[4 * stride], bz = x[5 * stride];
  const double cx = x[6 * stride], cy = x[7 * stride], cz = x[8 * stride];
  const double bcx = by * cz - bz * cy, bcy = bz * cx - bx * cz, bcz = bx * cy - by * cx;
  const double s6 = s / 6.0;
  out[0] = s6 * bcx;
  out[1 * out_stride] = s6 * bcy;
  out[2 * out_stride] = s6 * bcz;
  out[3 * out_stride] = s6 * (cy * az - cz * ay);
  out[4 * out_stride] = s6 * (cz * ax - cx * az);
  out[5 * out_stride] = s6 * (cx * ay - cy * ax);
  out[6 * out_stride] = s6 * (ay * bz - az * by);
  out[7 * out_stride] = s6 * (az * bx - ax * bz);
  out[8 * out_stride] = s6 * (ax * by - ay * bx);
  return ax * bcx + ay * bcy + az * bcz;
}

}  // namespace rbcal::solver
