#pragma once
// Two-relaxation-time (TRT) collision with Guo forcing for one D3Q19 node.
//
// Symmetric (even) moments relax with omega+ = 1/tau+, tau+ = 3 nu + 1/2, which sets
// the kinematic viscosity nu; antisymmetric (odd) moments relax with omega- chosen so
// that the "magic" parameter Lambda = (tau+ - 1/2)(tau- - 1/2) is fixed (3/16 puts
// half-way bounce-back walls exactly mid-link for Poiseuille flow: Ginzburg et al.,
// Commun. Comput. Phys. 3 (2008) 427). The Guo et al. (PRE 65, 046308, 2002) source
// S_q = w_q [3 (c_q - u).F + 9 (c_q.u)(c_q.F)] is split into its even and odd parts,
// each scaled by (1 - omega/2) of its own relaxation rate; the velocity is
// u = (sum_q f_q c_q + F/2) / rho. All quantities in lattice units.
#include "solver/d3q19.hpp"

namespace rbcal::solver {

struct TrtRates {
  double omega_plus;
  double omega_minus;
};

// Relaxation rates for kinematic viscosity nu (lattice units) and magic parameter Lambda.
inline TrtRates trt_rates(double nu, double magic) {
  const double tau_plus = 3.0 * nu + 0.5;
  const double tau_minus = 0.5 + magic / (3.0 * nu);
  return {1.0 / tau_plus, 1.0 / tau_minus};
}

// Collides the populations f of one node in place.
inline void collide_trt(double* f, double nu, double magic, double fx, double fy, double fz) {
  using namespace d3q19;
  double rho = 0.0, jx = 0.0, jy = 0.0, jz = 0.0;
  for (int q = 0; q < Q; ++q) {
    rho += f[q];
    jx += f[q] * c[q][0];
    jy += f[q] * c[q][1];
    jz += f[q] * c[q][2];
  }
  const double inv_rho = 1.0 / rho;
  const double ux = (jx + 0.5 * fx) * inv_rho;
  const double uy = (jy + 0.5 * fy) * inv_rho;
  const double uz = (jz + 0.5 * fz) * inv_rho;
  const double usq = ux * ux + uy * uy + uz * uz;
  const double uf = ux * fx + uy * fy + uz * fz;

  const TrtRates r = trt_rates(nu, magic);
  const double force_plus = 1.0 - 0.5 * r.omega_plus;
  const double force_minus = 1.0 - 0.5 * r.omega_minus;

  f[0] += -r.omega_plus * (f[0] - w[0] * rho * (1.0 - 1.5 * usq)) - force_plus * w[0] * 3.0 * uf;

  for (int q = 1; q < Q; q += 2) {
    const int qb = q + 1;  // opposite direction (see d3q19.hpp ordering)
    const double cu = c[q][0] * ux + c[q][1] * uy + c[q][2] * uz;
    const double cf = c[q][0] * fx + c[q][1] * fy + c[q][2] * fz;
    const double eq_plus = w[q] * rho * (1.0 + 4.5 * cu * cu - 1.5 * usq);
    const double eq_minus = w[q] * rho * 3.0 * cu;
    const double src_plus = w[q] * (9.0 * cu * cf - 3.0 * uf);
    const double src_minus = w[q] * 3.0 * cf;
    const double f_plus = 0.5 * (f[q] + f[qb]);
    const double f_minus = 0.5 * (f[q] - f[qb]);
    const double d_plus = -r.omega_plus * (f_plus - eq_plus) + force_plus * src_plus;
    const double d_minus = -r.omega_minus * (f_minus - eq_minus) + force_minus * src_minus;
    f[q] += d_plus + d_minus;
    f[qb] += d_plus - d_minus;
  }
}

}  // namespace rbcal::solver
