#include "solver/device/detail/device_kernels.hpp"

#include <chrono>
#include <cmath>
#include <utility>

#include "solver/coupling/kernel_stencil.hpp"
#include "solver/device/detail/device_runtime.hpp"
#include "solver/fluid/d3q19.hpp"
#include "solver/fluid/detail/trt_collision.hpp"

namespace rbcal::solver::device_kernels {

using device::atomic_add;
using device::atomic_max_nonnegative;
using device::for_each;

namespace {

// Calls f(std::integral_constant<int, q>) for every lattice direction q: the velocities and
// weights of q are then constant expressions, also in device code.
template <class F>
RBCAL_HD inline void for_each_direction(F&& f) {
  [&]<int... q>(std::integer_sequence<int, q...>) {
    (f(std::integral_constant<int, q>{}), ...);
  }(std::make_integer_sequence<int, d3q19::Q>{});
}

RBCAL_HD inline int wrap_once(int i, int n) { return i < 0 ? i + n : (i >= n ? i - n : i); }

// Velocity at a stencil from a node field (components `stride` apart), divided by steps.
RBCAL_HD inline void interpolate_at(const KernelStencil& s, const double* u, std::size_t stride, int ny, int nz,
                                    double steps, double* out) {
  double sx = 0.0, sy = 0.0, sz = 0.0;
  for_each_stencil_node(s, ny, nz, [&](std::size_t n, double w) {
    sx += w * u[n];
    sy += w * u[stride + n];
    sz += w * u[2 * stride + n];
  });
  out[0] = sx / steps;
  out[1] = sy / steps;
  out[2] = sz / steps;
}

// Gathers the coordinates of `count` nodes of one cell into out (x y z each).
RBCAL_HD inline void gather(const double* x, std::size_t first_node, const int* node, int count, double* out) {
  for (int k = 0; k < count; ++k)
    for (int d = 0; d < 3; ++d) out[3 * k + d] = x[3 * (first_node + node[k]) + d];
}

RBCAL_HD inline void scatter_add(double* forces, std::size_t first_node, int node, const double* f, double scale) {
  for (int d = 0; d < 3; ++d) atomic_add(&forces[3 * (first_node + node) + d], scale * f[d]);
}

template <MembraneLaw law>
void elastic_forces_of(const Cells& c, const double* x, const int* triangles, const ElasticElementReference* reference,
                       std::size_t triangle_count, double gs, double skalak_c, double* forces) {
  const std::size_t per_cell = c.nodes_per_cell;
  for_each(c.count * triangle_count, RBCAL_KERNEL_LAMBDA(std::size_t i) {
    const std::size_t cell = i / triangle_count, t = i % triangle_count;
    const std::size_t first = cell * per_cell;
    const int* node = triangles + 3 * t;
    double xe[9], out[6];
    gather(x, first, node, 3, xe);
    elastic_element_forces<law>(xe, 1, reference[t], gs, skalak_c, out, 1);
    const double sum[3] = {out[0] + out[3], out[1] + out[4], out[2] + out[5]};
    scatter_add(forces, first, node[1], out, 1.0);
    scatter_add(forces, first, node[2], out + 3, 1.0);
    scatter_add(forces, first, node[0], sum, -1.0);
  });
}

}  // namespace

namespace {

// A stored population as the update reads it: float storage holds f_q - w_q.
template <int q, class T>
RBCAL_HD inline double loaded(T stored) {
  if constexpr (sizeof(T) == sizeof(float)) {
    constexpr double rest = d3q19::w[q];
    return static_cast<double>(stored) + rest;
  } else {
    return stored;
  }
}

template <class T>
void fluid_update_of(const LatticeShape& l, const FluidUpdate& a, const T* f_in, T* f_out) {
  const int nx = l.nx, ny = l.ny, nz = l.nz;
  const std::size_t nodes = l.nodes;
  const double* nu = a.viscosity;
  const double* force = a.force;
  double* velocity = a.velocity;
  const bool accumulate = a.accumulate, walls = a.walls;
  const double u_bottom = a.u_bottom, u_top = a.u_top, magic = a.magic;
  for_each(nodes, RBCAL_KERNEL_LAMBDA(std::size_t n) {
    const int z = static_cast<int>(n % nz);
    const std::size_t xy = n / nz;
    const int y = static_cast<int>(xy % ny), x = static_cast<int>(xy / ny);
    double f[d3q19::Q];
    for_each_direction([&](auto direction) {
      constexpr int q = decltype(direction)::value;
      constexpr int cx = d3q19::c[q][0], cy = d3q19::c[q][1], cz = d3q19::c[q][2];
      const int ys = y - cy;
      if (walls && (ys < 0 || ys >= ny)) {
        // Half-way bounce-back with the moving-wall term (Ladd 1994), as FluidLattice
        // (the opposite direction has the same weight, so the same shift).
        constexpr int opposite = d3q19::opposite(q);
        constexpr double wall_term = 6.0 * d3q19::w[q] * cz;
        f[q] = loaded<q>(f_in[opposite * nodes + n]) + wall_term * (ys < 0 ? u_bottom : u_top);
      } else {
        const std::size_t from = lattice_index(wrap_once(x - cx, nx), wrap_once(ys, ny), wrap_once(z - cz, nz), ny, nz);
        f[q] = loaded<q>(f_in[q * nodes + from]);
      }
    });
    double u[3];
    collide_trt<double>(f, nu[n], magic, force[n], force[nodes + n], force[2 * nodes + n], u);
    T* const out = f_out + n;  // captured before the constexpr branch below (nvcc's rule)
    for_each_direction([&](auto direction) {
      constexpr int q = decltype(direction)::value;
      if constexpr (sizeof(T) == sizeof(float)) {
        constexpr double rest = d3q19::w[q];
        out[q * nodes] = static_cast<float>(f[q] - rest);
      } else {
        out[q * nodes] = f[q];
      }
    });
    if (velocity)
      for (int d = 0; d < 3; ++d) velocity[d * nodes + n] = accumulate ? velocity[d * nodes + n] + u[d] : u[d];
  });
}

template <class T>
void wall_shear_traction_of(const LatticeShape& l, const T* f, double u_bottom, double u_top, double* out) {
  const int ny = l.ny, nz = l.nz;
  const std::size_t nodes = l.nodes;
  const double area = static_cast<double>(l.nx) * nz;
  // One thread per x: each sums its rows along z, then adds to the totals.
  for_each(static_cast<std::size_t>(l.nx), RBCAL_KERNEL_LAMBDA(std::size_t xi) {
    const int x = static_cast<int>(xi);
    double bottom = 0.0, top = 0.0;
    for_each_direction([&](auto direction) {
      constexpr int q = decltype(direction)::value;
      constexpr int cy = d3q19::c[q][1], cz = d3q19::c[q][2];
      if (cz != 0 && cy != 0) {  // constant: the other directions compile to nothing
        // A population leaving a wall node towards the wall returns as f - 6 w (c . u_wall);
        // the wall receives c_q times their sum (FluidLattice::wall_traction).
        constexpr double wall_term = 6.0 * d3q19::w[q] * cz;
        const int y = cy < 0 ? 0 : ny - 1;
        const double correction = wall_term * (cy < 0 ? u_bottom : u_top);
        double exchanged = 0.0;
        const T* row = f + q * nodes + lattice_index(x, y, 0, ny, nz);
        for (int z = 0; z < nz; ++z) exchanged += 2.0 * loaded<q>(row[z]) - correction;
        (cy < 0 ? bottom : top) += cz * exchanged;
      }
    });
    atomic_add(&out[0], bottom / area);
    atomic_add(&out[1], top / area);
  });
}

}  // namespace

void fluid_update(const LatticeShape& l, const FluidUpdate& a) {
  if (a.h_in) fluid_update_of(l, a, a.h_in, a.h_out);
  else fluid_update_of(l, a, a.f_in, a.f_out);
}

void wall_shear_traction(const LatticeShape& l, const double* f, const float* h, double u_bottom, double u_top,
                         double* out) {
  if (h) wall_shear_traction_of(l, h, u_bottom, u_top, out);
  else wall_shear_traction_of(l, f, u_bottom, u_top, out);
}

void elastic_forces(MembraneLaw law, const Cells& c, const double* x, const int* triangles,
                    const ElasticElementReference* reference, std::size_t triangle_count, double shear_modulus,
                    double skalak_c, double* forces) {
  if (law == MembraneLaw::Skalak)
    elastic_forces_of<MembraneLaw::Skalak>(c, x, triangles, reference, triangle_count, shear_modulus, skalak_c, forces);
  else
    elastic_forces_of<MembraneLaw::NeoHookean>(c, x, triangles, reference, triangle_count, shear_modulus, skalak_c,
                                               forces);
}

void bending_forces(const Cells& c, const double* x, const int* hinges, const HingeReference* reference,
                    std::size_t hinge_count, double kd, double* forces) {
  const std::size_t per_cell = c.nodes_per_cell;
  for_each(c.count * hinge_count, RBCAL_KERNEL_LAMBDA(std::size_t i) {
    const std::size_t cell = i / hinge_count, h = i % hinge_count;
    const std::size_t first = cell * per_cell;
    const int* node = hinges + 4 * h;
    double xh[12], out[12], held_sq;
    gather(x, first, node, 4, xh);
    hinge_forces(xh, 1, reference[h], kd, out, 1, held_sq);
    // A collapsed wing's hold (dihedral_bending.hpp): a common factor of the hinge's forces.
    const double held = held_sq < 1.0 ? sqrt(held_sq) : 1.0;
    for (int k = 0; k < 4; ++k) scatter_add(forces, first, node[k], out + 3 * k, held);
  });
}

void volume_and_gradient(const Cells& c, const double* x, const int* triangles, std::size_t triangle_count,
                         double* volume, double* gradient) {
  const std::size_t per_cell = c.nodes_per_cell;
  for_each(c.count * triangle_count, RBCAL_KERNEL_LAMBDA(std::size_t i) {
    const std::size_t cell = i / triangle_count, t = i % triangle_count;
    const std::size_t first = cell * per_cell;
    const int* node = triangles + 3 * t;
    double xt[9], out[9];
    gather(x, first, node, 3, xt);
    atomic_add(&volume[cell], triangle_volume_gradient(xt, 1, 1.0, out, 1) / 6.0);
    if (gradient)
      for (int k = 0; k < 3; ++k) scatter_add(gradient, first, node[k], out + 3 * k, 1.0);
  });
}

void add_volume_penalty(const Cells& c, const double* gradient, const double* volume, double stiffness, double v0,
                        double* forces) {
  const std::size_t per_cell = c.nodes_per_cell;
  for_each(c.nodes(), RBCAL_KERNEL_LAMBDA(std::size_t g) {
    const double scale = -stiffness * (volume[g / per_cell] - v0) / v0;
    for (int d = 0; d < 3; ++d) forces[3 * g + d] += scale * gradient[3 * g + d];
  });
}

void spread_forces(const LatticeShape& l, KernelKind kernel, std::size_t nodes, const double* x, const double* forces,
                   double* force_field) {
  const int nx = l.nx, ny = l.ny, nz = l.nz;
  const std::size_t stride = l.nodes;
  for_each(nodes, RBCAL_KERNEL_LAMBDA(std::size_t g) {
    const KernelStencil s = make_stencil(kernel, x[3 * g], x[3 * g + 1], x[3 * g + 2], nx, ny, nz);
    const double fx = forces[3 * g], fy = forces[3 * g + 1], fz = forces[3 * g + 2];
    for_each_stencil_node(s, ny, nz, [&](std::size_t n, double w) {
      atomic_add(&force_field[n], w * fx);
      atomic_add(&force_field[stride + n], w * fy);
      atomic_add(&force_field[2 * stride + n], w * fz);
    });
  });
}

void interpolate_velocities(const LatticeShape& l, KernelKind kernel, std::size_t nodes, const double* x,
                            const double* velocity_field, double field_steps, bool rk4, double dt, double* v,
                            double* max_speed2) {
  const int nx = l.nx, ny = l.ny, nz = l.nz;
  const std::size_t stride = l.nodes;
  for_each(nodes, RBCAL_KERNEL_LAMBDA(std::size_t g) {
    const double p[3] = {x[3 * g], x[3 * g + 1], x[3 * g + 2]};
    auto velocity_at = [&](const double* at, double* u) {
      interpolate_at(make_stencil(kernel, at[0], at[1], at[2], nx, ny, nz), velocity_field, stride, ny, nz,
                     field_steps, u);
    };
    double u1[3];
    velocity_at(p, u1);
    double vel[3] = {u1[0], u1[1], u1[2]};
    if (rk4) {
      // Classical RK4 through the velocity field of this step (over dt).
      double u2[3], u3[3], u4[3], q[3];
      for (int d = 0; d < 3; ++d) q[d] = p[d] + (0.5 * dt) * u1[d];
      velocity_at(q, u2);
      for (int d = 0; d < 3; ++d) q[d] = p[d] + (0.5 * dt) * u2[d];
      velocity_at(q, u3);
      for (int d = 0; d < 3; ++d) q[d] = p[d] + dt * u3[d];
      velocity_at(q, u4);
      for (int d = 0; d < 3; ++d) vel[d] = (u1[d] + 2.0 * u2[d] + 2.0 * u3[d] + u4[d]) / 6.0;
    }
    for (int d = 0; d < 3; ++d) v[3 * g + d] = vel[d];
    atomic_max_nonnegative(max_speed2, vel[0] * vel[0] + vel[1] * vel[1] + vel[2] * vel[2]);
  });
}

void advance_positions(std::size_t nodes, const double* v, double dt, double* x) {
  for_each(3 * nodes, RBCAL_KERNEL_LAMBDA(std::size_t i) { x[i] += dt * v[i]; });
}

void correct_volumes(const Cells& c, const double* gradient, const double* volume, double v0, double* norm2,
                     double* x) {
  const std::size_t per_cell = c.nodes_per_cell;
  for_each(c.nodes(), RBCAL_KERNEL_LAMBDA(std::size_t g) {
    const double* n = gradient + 3 * g;
    atomic_add(&norm2[g / per_cell], n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  });
  for_each(c.nodes(), RBCAL_KERNEL_LAMBDA(std::size_t g) {
    const std::size_t cell = g / per_cell;
    const double s = (v0 - volume[cell]) / norm2[cell];
    for (int d = 0; d < 3; ++d) x[3 * g + d] += s * gradient[3 * g + d];
  });
}

void max_displacement2(std::size_t nodes, const double* x, const double* x_ref, double* out) {
  for_each(nodes, RBCAL_KERNEL_LAMBDA(std::size_t g) {
    double s = 0.0;
    for (int d = 0; d < 3; ++d) {
      const double dx = x[3 * g + d] - x_ref[3 * g + d];
      s += dx * dx;
    }
    atomic_max_nonnegative(out, s);
  });
}

void inside_crossings(const LatticeShape& l, int lines_per_spacing, const Cells& c, const double* x,
                      const int* triangles, std::size_t triangle_count, double* partial, double* jump,
                      double* column_base, int* oversized) {
  const int nx = l.nx, ny = l.ny, nz = l.nz, sub = lines_per_spacing;
  const std::size_t per_cell = c.nodes_per_cell;
  for_each(c.count * triangle_count, RBCAL_KERNEL_LAMBDA(std::size_t i) {
    // The scan-line geometry of InsideFraction (inside_fraction.cpp), offsets included.
    constexpr double kLineOffsetX = 1.0e-7 * 3.14159265358979;
    constexpr double kLineOffsetY = 1.0e-7 * 2.71828182845905;
    const std::size_t cell = i / triangle_count, t = i % triangle_count;
    double xt[9];
    gather(x, cell * per_cell, triangles + 3 * t, 3, xt);
    const double ax = xt[0], ay = xt[1], az = xt[2], bx = xt[3], by = xt[4], bz = xt[5];
    const double cx = xt[6], cy = xt[7], cz = xt[8];
    const double area2 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    if (area2 == 0.0) return;  // edge-on to the scan lines
    const double sign = area2 > 0.0 ? -1.0 : 1.0;  // normal along +z: leaving the interior
    const double inv_area2 = 1.0 / area2;
    const double h = 1.0 / sub, weight = h * h;
    auto first_line = [&](double lo, double offset) { return static_cast<int>(ceil((lo + 0.5 - offset) * sub - 0.5)); };
    auto last_line = [&](double hi, double offset) { return static_cast<int>(floor((hi + 0.5 - offset) * sub - 0.5)); };
    const double xlo = fmin(ax, fmin(bx, cx)), xhi = fmax(ax, fmax(bx, cx));
    const double ylo = fmin(ay, fmin(by, cy)), yhi = fmax(ay, fmax(by, cy));
    if (!(xhi - xlo < nx && yhi - ylo < ny + 1)) {  // NaN coordinates too
      *oversized = 1;  // every writer writes 1
      return;
    }
    const int p0 = first_line(xlo, kLineOffsetX), p1 = last_line(xhi, kLineOffsetX);
    const int q0 = first_line(ylo, kLineOffsetY), q1 = last_line(yhi, kLineOffsetY);
    for (int p = p0; p <= p1; ++p)
      for (int q = q0; q <= q1; ++q) {
        const int j = floor_div(q, sub);
        if (j < 0 || j >= ny) continue;  // beyond a wall: no nodes
        const double px = (p + 0.5) * h - 0.5 + kLineOffsetX, py = (q + 0.5) * h - 0.5 + kLineOffsetY;
        // Barycentric weights of (px, py) in the projected triangle.
        const double wa = ((bx - px) * (cy - py) - (by - py) * (cx - px)) * inv_area2;
        const double wb = ((cx - px) * (ay - py) - (cy - py) * (ax - px)) * inv_area2;
        const double wc = 1.0 - wa - wb;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
        const double z = wa * az + wb * bz + wc * cz;
        // The crossing in the box's image in z, [-1/2, nz - 1/2), and the image's number.
        const double image = floor((z + 0.5) / nz);
        const double zw = z - image * nz;
        const int k = static_cast<int>(fmin(fmax(floor(zw + 0.5), 0.0), nz - 1.0));
        const int column_x = wrap_index(floor_div(p, sub), nx);
        const std::size_t column = static_cast<std::size_t>(column_x) * ny + j;
        const std::size_t node = column * nz + k;
        atomic_add(&partial[node], sign * weight * (k + 0.5 - zw));
        if (k + 1 < nz) atomic_add(&jump[node + 1], sign * weight);
        if (image != 0.0) atomic_add(&column_base[column], -sign * weight * image);
      }
  });
}

void viscosity_from_crossings(const LatticeShape& l, const double* partial, const double* jump,
                              const double* column_base, double nu_out, double lambda, double* viscosity) {
  const int nz = l.nz;
  for_each(static_cast<std::size_t>(l.nx) * l.ny, RBCAL_KERNEL_LAMBDA(std::size_t column) {
    double winding = column_base[column];
    const std::size_t first = column * nz;
    for (int k = 0; k < nz; ++k) {
      winding += jump[first + k];
      const double alpha = fmin(1.0, fmax(0.0, winding + partial[first + k]));
      viscosity[first + k] = nu_out * (1.0 + (lambda - 1.0) * alpha);
    }
  });
}

double copy_bandwidth(std::size_t bytes, int repeats) {
  const std::size_t n = bytes / sizeof(double);
  device::Buffer<double> a(n), b(n);
  b.copy_from(a);  // warm-up
  device::synchronize();
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < repeats; ++r) b.copy_from(a);
  device::synchronize();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return 2.0 * static_cast<double>(n * sizeof(double)) * repeats / seconds;
}

}  // namespace rbcal::solver::device_kernels
