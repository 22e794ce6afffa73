#pragma once
// Two-relaxation-time (TRT) collision with Guo forcing for D3Q19 nodes.
//
// Symmetric (even) moments relax with omega+ = 1/tau+, tau+ = 3 nu + 1/2, which sets
// the kinematic viscosity nu; antisymmetric (odd) moments relax with omega- chosen so
// that the "magic" parameter Lambda = (tau+ - 1/2)(tau- - 1/2) is fixed (3/16 puts
// half-way bounce-back walls exactly mid-link for Poiseuille flow: Ginzburg et al.,
// Commun. Comput. Phys. 3 (2008) 427). The Guo et al. (PRE 65, 046308, 2002) source
// S_q = w_q [3 (c_q - u).F + 9 (c_q.u)(c_q.F)] is split into its even and odd parts,
// each scaled by (1 - omega/2) of its own relaxation rate; the velocity is
// u = (sum_q f_q c_q + F/2) / rho. All quantities in lattice units.
//
// Written once for a scalar node (T = double) and for a vector of nodes
// (T = simd::vdouble); the lattice velocities are template parameters so that the
// zero components cost nothing.
#include <utility>

#include "solver/device/host_device.hpp"
#include "solver/fluid/d3q19.hpp"

// The collision, its pairs of directions included, inlined into the fluid update on the
// CPU: GCC left them out of line, and the populations and moments then went through memory
// for every pair (inlined, the update 6-11 % faster at two threads, with eight doubles per
// vector and with four). Left to the compiler under nvcc.
#if defined(__CUDACC__)
#define RBCAL_TRT_INLINE
#else
#define RBCAL_TRT_INLINE __attribute__((always_inline))
#endif

namespace rbcal::solver {

namespace trt_detail {

using d3q19::c;

// s * v for a lattice-velocity component s in {-1, 0, 1}, added to sum.
template <int s, class T>
RBCAL_HD inline T accumulate(T sum, T v) {
  if constexpr (s == 1) return sum + v;
  else if constexpr (s == -1) return sum - v;
  else return sum;
}

// c_q . (x, y, z) without multiplications.
template <int q, class T>
RBCAL_HD inline T dot_c(T x, T y, T z) {
  T r = T{};
  r = accumulate<c[q][0]>(r, x);
  r = accumulate<c[q][1]>(r, y);
  r = accumulate<c[q][2]>(r, z);
  return r;
}

template <int d, class T, int... q>
RBCAL_HD inline T first_moment(const T* f, std::integer_sequence<int, q...>) {
  T sum = T{};
  ((sum = accumulate<c[q][d]>(sum, f[q])), ...);
  return sum;
}

}  // namespace trt_detail

// Collides the populations f[0..18] of one node (or one vector of nodes) in place; with
// u_out, also stores the velocity u that entered the collision (x, y, z).
template <class T>
RBCAL_HD RBCAL_TRT_INLINE inline void collide_trt(T* f, T nu, double magic, T fx, T fy, T fz, T* u_out = nullptr) {
  using namespace d3q19;
  using namespace trt_detail;
  constexpr auto all = std::make_integer_sequence<int, Q>{};

  T rho = f[0];
  for (int q = 1; q < Q; ++q) rho = rho + f[q];
  const T inv_rho = 1.0 / rho;
  const T ux = (first_moment<0>(f, all) + 0.5 * fx) * inv_rho;
  const T uy = (first_moment<1>(f, all) + 0.5 * fy) * inv_rho;
  const T uz = (first_moment<2>(f, all) + 0.5 * fz) * inv_rho;
  if (u_out) {
    u_out[0] = ux;
    u_out[1] = uy;
    u_out[2] = uz;
  }
  const T usq = ux * ux + uy * uy + uz * uz;
  const T uf = ux * fx + uy * fy + uz * fz;

  // tau+ = 3 nu + 1/2, tau- = 1/2 + Lambda / (3 nu).
  const T omega_plus = 1.0 / (3.0 * nu + 0.5);
  const T omega_minus = 1.0 / (0.5 + magic / (3.0 * nu));
  const T force_plus = 1.0 - 0.5 * omega_plus;
  const T force_minus = 1.0 - 0.5 * omega_minus;
  const T base = rho * (1.0 - 1.5 * usq);  // rho (1 - 3/2 u^2)

  // The weights bound to constexpr locals: evaluated at compile time, also in device code.
  constexpr double w0 = w[0];
  f[0] = f[0] - omega_plus * (f[0] - w0 * base) - force_plus * (w0 * 3.0) * uf;

  auto pair = [&]<int q>(std::integral_constant<int, q>) RBCAL_TRT_INLINE {
    constexpr int qb = q + 1;  // opposite direction (see d3q19.hpp ordering)
    const T cu = dot_c<q>(ux, uy, uz);
    const T cf = dot_c<q>(fx, fy, fz);
    constexpr double wq = w[q];
    const T eq_plus = wq * (base + (4.5 * rho) * cu * cu);
    const T eq_minus = (wq * 3.0) * rho * cu;
    const T src_plus = wq * (9.0 * cu * cf - 3.0 * uf);
    const T src_minus = (wq * 3.0) * cf;
    const T f_plus = 0.5 * (f[q] + f[qb]);
    const T f_minus = 0.5 * (f[q] - f[qb]);
    const T d_plus = force_plus * src_plus - omega_plus * (f_plus - eq_plus);
    const T d_minus = force_minus * src_minus - omega_minus * (f_minus - eq_minus);
    f[q] = f[q] + (d_plus + d_minus);
    f[qb] = f[qb] + (d_plus - d_minus);
  };
  [&]<int... p>(std::integer_sequence<int, p...>) RBCAL_TRT_INLINE {
    (pair(std::integral_constant<int, 2 * p + 1>{}), ...);
  }(std::make_integer_sequence<int, (Q - 1) / 2>{});
}

}  // namespace rbcal::solver
