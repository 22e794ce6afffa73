#pragma once
// Reference shapes of cells: icosahedral subdivision meshes (20 * 4^k triangles: 320,
// 1280 and 5120 for k = 2, 3, 4) mapped to a sphere or to the biconcave red blood cell.
//
// Biconcave profile (Evans & Fung, Microvasc. Res. 4 (1972) 335), axis of symmetry z,
// rho = r / a in [0, 1]:  z(rho) = +-(a/2) s sqrt(1 - rho^2) (C0 + C2 rho^2 + C4 rho^4),
// C0 = 0.207161, C2 = 2.002558, C4 = -1.122762. With s = 1 (the published shape scaled
// to major radius a) the maximum thickness is 0.6562 a (2.57 um at a = 3.91 um); the seed
// study states a maximum thickness of a/2, which s = 0.7620 gives. A unit-sphere point
// (x, y, z) maps to (a x, a y, (a/2) s z (C0 + C2 rho^2 + C4 rho^4)) with rho^2 = x^2 + y^2.
#include <string>

#include "solver/membrane/triangle_mesh.hpp"

namespace rbcal::solver {

enum class BiconcaveProfile {
  EvansFung,      // published profile scaled to radius a (max thickness 0.656 a)
  SeedThickness,  // same profile flattened to the seed study's max thickness a/2
};

std::string to_string(BiconcaveProfile profile);
BiconcaveProfile biconcave_profile_from_string(const std::string& name);  // "evans-fung" | "seed"

// Unit icosphere with 20 * 4^subdivisions triangles.
TriangleMesh make_icosphere(int subdivisions);

// Subdivision level for 20 * 4^k triangles; throws std::invalid_argument otherwise.
int subdivisions_for(int triangles);

TriangleMesh make_sphere(int triangles, double radius);
TriangleMesh make_biconcave_cell(int triangles, double radius, BiconcaveProfile profile);
// Oblate (aspect_ratio < 1) or prolate spheroid about z: equatorial semi-axis radius, polar
// semi-axis aspect_ratio * radius. A stiff one is the rigid body of known intrinsic
// viscosity (solver/membrane/rigid_spheroid_viscosity.hpp) that measures the immersed boundary's
// thickening of a thin cell.
TriangleMesh make_spheroid(int triangles, double radius, double aspect_ratio);

// Maximum thickness of the profile in units of the radius a.
double biconcave_max_thickness(BiconcaveProfile profile);

struct MeshQuality {
  double min_edge = 0, max_edge = 0, mean_edge = 0;
  double edge_spread = 0;  // max_edge / min_edge
  double min_angle_deg = 0, max_angle_deg = 0;
};

MeshQuality mesh_quality(const TriangleMesh& mesh);

}  // namespace rbcal::solver
