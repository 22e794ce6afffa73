#pragma once
// The intrinsic viscosity of a rigid spheroid that spins about its symmetry axis held
// along the vorticity (the "rolling" or log-rolling Jeffery orbit, orbit constant 0):
// a steady state, stable for oblate spheroids thicker than about 1 : 7 at small Reynolds
// number (Einarsson et al., Phys. Fluids 27 (2015) 063301), so a short run measures it.
//
// In that orbit the shear's rate of strain lies in the equatorial plane, and the
// torque-free stresslet is S = (16 pi mu / 3) E / ((b^2 + b^2) J'), Jeffery's off-diagonal
// result for an ellipsoid with semi-axes (b, b, a) (G. B. Jeffery, Proc. R. Soc. Lond. A 102
// (1922) 161), with
//
//     J' = int_0^inf dx / ((x + b^2)^3 sqrt(x + a^2)),
//
// so that eta_sp / phi = S_xy / (mu gamma_dot V) = 1 / (a b^4 J'). For a sphere J' =
// (2/5) b^-5 and the value is Einstein's 5/2; for a thin disc (a -> 0) it tends to
// 8 / (3 pi a / b), so eta_sp tends to (32/9) n b^3, set by the diameter alone.
namespace rbcal::solver {

// J' for polar semi-axis a and equatorial semi-axis b (any a, b > 0).
double jeffery_equatorial_integral(double polar, double equatorial);

// eta_sp / phi of a dilute suspension of rigid spheroids in the rolling orbit: a function
// of the aspect ratio a / b alone.
double rolling_spheroid_intrinsic_viscosity(double aspect_ratio);

}  // namespace rbcal::solver
