#pragma once
// Particle stresslet of a capsule (Pozrikidis, J. Fluid Mech. 297 (1995) 123; the seed
// study's eq. for Sigma^(p)):
//   S = integral over the membrane of [ (r q + q r)/2 - eta0 (1 - lambda) (v n + n v) ] dA,
// r the position relative to the cell's centroid, q the load the fluid exerts on the
// membrane, v the membrane velocity and n the outward normal. The membrane is in
// equilibrium with its load, so q dA at a node is minus the membrane force there
// (F_i = -dW/dx_i, the force the IBM spreads to the fluid); n dA at a node is a third of
// the area-weighted normals of its triangles. The particle stress of a suspension is
// Sigma_p = sum_cells S / V_box and eta_sp = Sigma_p[z][y] / (eta0 gamma_dot) with z
// streamwise and y wall-normal. Any consistent units (lattice units in the solver).
#include <Eigen/Core>
#include <vector>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

using Mat3 = Eigen::Matrix3d;

Mat3 cell_stresslet(const std::vector<Vec3>& x, const std::vector<Vec3>& membrane_forces,
                    const std::vector<Vec3>& velocities, const std::vector<Triangle>& triangles, double eta0,
                    double viscosity_ratio);

// Taylor deformation D = (L - B)/(L + B) and inclination of a closed mesh in the shear
// plane (y, z): L and B are the semi-axes of the ellipse with the same second moments of
// volume (int r r dV = V a^2 / 5 for an ellipsoid), the angle is that of the major axis
// from the flow direction z towards +y, in radians.
struct ShearPlaneShape {
  double taylor_deformation = 0.0;
  double inclination = 0.0;
  double major = 0.0, minor = 0.0;
};

ShearPlaneShape shear_plane_shape(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles);

// Unit vector along the smallest principal second moment of the enclosed volume: the
// symmetry axis of a discocyte (sign arbitrary). Its component along the vorticity x tells
// rolling (|n_x| -> 1, the disc spins in the shear plane) from tumbling (n_x -> 0).
Vec3 short_axis(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles);

// Second moment of the enclosed volume about the volume centroid, and the centroid.
Mat3 volume_second_moment(const std::vector<Vec3>& x, const std::vector<Triangle>& triangles, Vec3* centroid = nullptr);

}  // namespace rbcal::solver
