#pragma once
// The loops of the device path (device_stepper.hpp), one function per loop, each over the
// lattice nodes, the membrane nodes or the membrane elements of all cells. Compiled by
// nvcc they launch GPU kernels; otherwise they run on the host's threads
// (device_runtime.hpp). They take raw arrays in the device's layout:
//   populations  f[q * nodes + n], n = (x * ny + y) * nz + z (FluidLattice::index);
//   node fields  force, velocity: component d at d * nodes + n; viscosity nu[n];
//   membranes    x[3 * (cell * nodes_per_cell + m) + d], likewise velocities and forces.
// (Free functions in a named namespace: nvcc's host-device lambdas may not live in a
// private member function.)
#include <cstddef>
#include <cstdint>

#include "solver/coupling/peskin_kernel.hpp"
#include "solver/membrane/element_forces.hpp"
#include "solver/membrane/strain_energy.hpp"

namespace rbcal::solver::device_kernels {

struct LatticeShape {
  int nx, ny, nz;
  std::size_t nodes;
};

// Populations in double, or in float as f_q - w_q (FluidConfig::single_precision): exactly
// one of the two pairs is set.
struct FluidUpdate {
  const double* f_in;
  double* f_out;
  const float* h_in;
  float* h_out;
  const double* viscosity;
  const double* force;
  double* velocity;  // nullptr: not written
  bool accumulate;   // add the velocity to what `velocity` holds
  bool walls;        // moving walls in y (else periodic)
  double u_bottom, u_top, magic;
};
// One pull-stream + TRT collision of every node (FluidLattice::step).
void fluid_update(const LatticeShape& l, const FluidUpdate& a);

// Wall shear traction (z components of FluidLattice::wall_traction) into out[0] (bottom),
// out[1] (top), which must hold zeros; per unit area.
// (f or h: the populations, as in FluidUpdate.)
void wall_shear_traction(const LatticeShape& l, const double* f, const float* h, double u_bottom, double u_top,
                         double* out);

struct Cells {
  std::size_t count, nodes_per_cell;
  std::size_t nodes() const { return count * nodes_per_cell; }
};

// Adds the elastic forces of every triangle to forces.
void elastic_forces(MembraneLaw law, const Cells& c, const double* x, const int* triangles,
                    const ElasticElementReference* reference, std::size_t triangle_count, double shear_modulus,
                    double skalak_c, double* forces);
// Adds the bending forces of every hinge (a, b, c, d) to forces.
void bending_forces(const Cells& c, const double* x, const int* hinges, const HingeReference* reference,
                    std::size_t hinge_count, double kd, double* forces);
// Adds each cell's enclosed volume to volume[cell] and, with gradient, dV/dx to gradient.
void volume_and_gradient(const Cells& c, const double* x, const int* triangles, std::size_t triangle_count,
                         double* volume, double* gradient);
// forces += -k_v (V - V0) / V0 dV/dx per cell (the volume penalty).
void add_volume_penalty(const Cells& c, const double* gradient, const double* volume, double stiffness, double v0,
                        double* forces);

// Adds each membrane node's force through its kernel stencil to the force field.
void spread_forces(const LatticeShape& l, KernelKind kernel, std::size_t nodes, const double* x, const double* forces,
                   double* force_field);

// Node velocities from the velocity field (a sum over `field_steps` fluid steps), Euler
// or RK4 through it over dt; the largest squared speed into *max_speed2 (holding 0).
void interpolate_velocities(const LatticeShape& l, KernelKind kernel, std::size_t nodes, const double* x,
                            const double* velocity_field, double field_steps, bool rk4, double dt, double* v,
                            double* max_speed2);
// x += dt v.
void advance_positions(std::size_t nodes, const double* v, double dt, double* x);
// The volume correction of correct_volume for every cell: x += (V0 - V) / |dV/dx|^2 dV/dx,
// with volume and gradient from volume_and_gradient and norm2 (zeros) as scratch.
void correct_volumes(const Cells& c, const double* gradient, const double* volume, double v0, double* norm2,
                     double* x);
// Largest squared distance between x and x_ref into *out (holding 0).
void max_displacement2(std::size_t nodes, const double* x, const double* x_ref, double* out);

// The inside fraction (inside_fraction.hpp) as signed steps: every crossing of a scan line
// with a triangle adds, with its sign, the part of its node above the crossing to
// partial[node] and a whole unit to jump[node + 1] (and to column_base for crossings in a
// periodic image in z); a scan up each column then sums them. All three hold zeros on
// entry. A triangle wider than the lattice (a blown-up membrane) sets *oversized.
void inside_crossings(const LatticeShape& l, int lines_per_spacing, const Cells& c, const double* x,
                      const int* triangles, std::size_t triangle_count, double* partial, double* jump,
                      double* column_base, int* oversized);
// nu = nu_out (1 + (lambda - 1) alpha), alpha from the steps, clamped to [0, 1].
void viscosity_from_crossings(const LatticeShape& l, const double* partial, const double* jump,
                              const double* column_base, double nu_out, double lambda, double* viscosity);

// Device-to-device copy bandwidth, bytes read and written per second, over a buffer of
// `bytes` (the yardstick of the fluid update's bandwidth on a GPU).
double copy_bandwidth(std::size_t bytes, int repeats);

}  // namespace rbcal::solver::device_kernels
